// lcm_consumer.cpp - trk's installed C++ LCM types (header-only, lcm-gen -x)
// in an external program (make install-check):
//   c++ -std=c++11 -I$(pkg-config --variable=cppincludedir trk-lcm) lcm_consumer.cpp
// Encodes a trk::track_list_t and decodes it back. Exit status 0, or 1.
#include <cstdio>
#include <vector>

#include "trk/track_list_t.hpp"

int main()
{
    trk::track_list_t m = trk::track_list_t();
    m.utime = 1700000000000000LL;
    m.n_tracks = 1;
    m.tracks[0].id = 42;
    m.tracks[0].status = trk::track_t::STATUS_CONFIRMED;
    m.tracks[0].x[2] = 7.5;
    std::vector<char> buf(m.getEncodedSize());
    int n = m.encode(buf.data(), 0, (int)buf.size());
    trk::track_list_t d;
    int k = d.decode(buf.data(), 0, (int)buf.size());
    bool ok = n == (int)buf.size() && k == n && d.utime == m.utime && d.n_tracks == 1 && d.tracks[0].id == 42 &&
              d.tracks[0].status == trk::track_t::STATUS_CONFIRMED && d.tracks[0].x[2] == 7.5;
    std::printf("lcm_consumer.cpp: %s: trk::track_list_t of %d bytes encoded and decoded (track %lld)\n",
                ok ? "ok" : "FAILED", n, (long long)d.tracks[0].id);
    return ok ? 0 : 1;
}
