// TrkSpyCheck - test of lcm-spy with trk's message types (make test-lcm-spy).
//
//   trk-lcm-spy with TRK_SPY_MAIN=lcm.spy.TrkSpyCheck:
//   TrkSpyCheck URL SCREENSHOT.png TIMEOUT_S CHANNEL=TYPE=COUNT ...
//
// Starts lcm-spy (new lcm.spy.Spy(URL), what lcm-spy's main does: its window
// and its subscription to every channel), waits until every CHANNEL has
// COUNT messages (or TIMEOUT_S), then reads lcm-spy's channel table (the
// table its window shows, through its table model) and checks, for each
// channel: the row is there, the Type column names TYPE and its class is
// trk.TYPE (lcm-spy found trk's class by the message fingerprint and decoded
// the message), Num Msgs is
// COUNT and Undecodable is 0. Prints the table, the last track list lcm-spy
// decoded (utime, tracks, confirmed ones), writes a screenshot of the
// "LCM Spy" window (SCREENSHOT.png), opens lcm-spy's viewer of TRK_TRACKS
// (what a double click on the row opens: the decoded fields) and writes its
// screenshot (SCREENSHOT-tracks.png). Exit status 0 when every check holds, 1 otherwise.
//
// In package lcm.spy: lcm-spy keeps its channel table package-private.
package lcm.spy;

import java.awt.Frame;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.io.File;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;
import javax.swing.table.TableModel;

public class TrkSpyCheck {
    static String[][] table(final Spy spy) throws Exception {
        final String[][][] out = new String[1][][];
        SwingUtilities.invokeAndWait(new Runnable() {
            public void run() {
                TableModel m = spy.channelTable.getModel();
                String[][] t = new String[m.getRowCount() + 1][m.getColumnCount()];
                for (int c = 0; c < m.getColumnCount(); c++) t[0][c] = m.getColumnName(c);
                for (int r = 0; r < m.getRowCount(); r++)
                    for (int c = 0; c < m.getColumnCount(); c++) t[r + 1][c] = String.valueOf(m.getValueAt(r, c)).trim();
                out[0] = t;
            }
        });
        return out[0];
    }

    static int column(String[][] t, String name) {
        for (int c = 0; c < t[0].length; c++)
            if (t[0][c].equals(name)) return c;
        throw new IllegalStateException("lcm-spy's table has no column " + name);
    }

    // Screenshot of the window titled `title` into png: 0, or 1 (a failure
    // printed) when no such window shows or its picture is blank.
    static int screenshot(String title, String png) throws Exception {
        Frame win = null;
        for (Frame f : Frame.getFrames())
            if (title.equals(f.getTitle()) && f.isShowing()) win = f;
        if (win == null) {
            System.out.printf("FAIL: no \"%s\" window showing%n", title);
            return 1;
        }
        Rectangle b = win.getBounds();
        BufferedImage img = new Robot().createScreenCapture(b);
        Set<Integer> colours = new HashSet<Integer>();
        for (int y = 0; y < img.getHeight(); y += 2)
            for (int x = 0; x < img.getWidth(); x += 2) colours.add(img.getRGB(x, y));
        ImageIO.write(img, "png", new File(png));
        System.out.printf("window \"%s\" %dx%d at (%d,%d): screenshot %s, %d colours%n", title, b.width, b.height, b.x,
                          b.y, png, colours.size());
        if (colours.size() < 3) {
            System.out.printf("FAIL: the screenshot of \"%s\" is blank%n", title);
            return 1;
        }
        return 0;
    }

    public static void main(String[] args) throws Exception {
        if (args.length < 4) {
            System.err.println("usage: TrkSpyCheck URL SCREENSHOT.png TIMEOUT_S CHANNEL=TYPE=COUNT ...");
            System.exit(2);
        }
        Map<String, String[]> want = new LinkedHashMap<String, String[]>();
        for (int i = 3; i < args.length; i++) {
            String[] f = args[i].split("=");
            want.put(f[0], new String[] {f[1], f[2]});
        }
        final Spy spy = new Spy(args[0]);
        long deadline = System.currentTimeMillis() + (long) (Double.parseDouble(args[2]) * 1000);
        String[][] t;
        int cName, cType, cNum, cBad;
        for (;;) {
            t = table(spy);
            cName = column(t, "Channel");
            cType = column(t, "Type");
            cNum = column(t, "Num Msgs");
            cBad = column(t, "Undecodable");
            int done = 0;
            for (int r = 1; r < t.length; r++) {
                String[] w = want.get(t[r][cName]);
                if (w != null && Long.parseLong(t[r][cNum]) >= Long.parseLong(w[1])) done++;
            }
            if (done == want.size() || System.currentTimeMillis() > deadline) break;
            Thread.sleep(200);
        }
        Thread.sleep(1000); // nothing more may arrive: the counts must stay
        t = table(spy);
        System.out.printf("lcm-spy channel table (%d rows):%n", t.length - 1);
        for (int r = 0; r < t.length; r++)
            System.out.printf("  %-20s %-24s %9s %11s%n", t[r][cName], t[r][cType], t[r][cNum], t[r][cBad]);
        int failures = 0;
        Set<String> seen = new HashSet<String>();
        for (int r = 1; r < t.length; r++) {
            String[] w = want.get(t[r][cName]);
            if (w == null) continue;
            seen.add(t[r][cName]);
            // the Type column shows the class's simple name; its full name is trk.<TYPE>
            ChannelData cd = spy.channelMap.get(t[r][cName]);
            String cls = cd != null && cd.cls != null ? cd.cls.getName() : "none";
            if (!t[r][cType].equals(w[0]) || !cls.equals("trk." + w[0]) || !t[r][cNum].equals(w[1]) ||
                !t[r][cBad].equals("0")) {
                System.out.printf("FAIL: %s: type %s (class %s), %s messages, %s undecodable; want %s (trk.%s), %s, 0%n",
                                  t[r][cName], t[r][cType], cls, t[r][cNum], t[r][cBad], w[0], w[0], w[1]);
                failures++;
            }
        }
        for (String ch : want.keySet())
            if (!seen.contains(ch)) {
                System.out.printf("FAIL: channel %s not in lcm-spy's table%n", ch);
                failures++;
            }
        ChannelData tracks = spy.channelMap.get("TRK_TRACKS");
        if (tracks != null && tracks.last instanceof trk.track_list_t) {
            trk.track_list_t m = (trk.track_list_t) tracks.last;
            int conf = 0;
            for (int i = 0; i < m.n_tracks; i++) conf += m.tracks[i].status == trk.track_t.STATUS_CONFIRMED ? 1 : 0;
            System.out.printf("last TRK_TRACKS decoded by lcm-spy: utime %d, seq %d, %d tracks, %d confirmed%n",
                              m.utime, m.seq, m.n_tracks, conf);
        } else if (want.containsKey("TRK_TRACKS")) {
            System.out.println("FAIL: lcm-spy holds no decoded trk.track_list_t on TRK_TRACKS");
            failures++;
        }
        failures += screenshot("LCM Spy", args[1]);
        // the viewer of TRK_TRACKS (what a double click on its row opens): the decoded fields
        if (tracks != null) {
            final ChannelData cd = tracks;
            SwingUtilities.invokeAndWait(new Runnable() {
                public void run() { spy.createViewer(cd); }
            });
            Thread.sleep(1500);
            failures += screenshot("TRK_TRACKS", args[1].replaceAll("\\.png$", "") + "-tracks.png");
        }
        System.out.println(failures == 0 ? "TrkSpyCheck: ok" : "TrkSpyCheck: " + failures + " failures");
        System.exit(failures == 0 ? 0 : 1);
    }
}
