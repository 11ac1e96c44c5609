/* test_fileio.c - fileio_read (tools/cli/fileio.h): whole files of any
 * size byte for byte with a NUL after them, empty files, and a missing file
 * (NULL, errno from fopen, length 0); the bound of fileio_read_max (an
 * endless /dev/zero refused); the atomic writer: a failed write (a file size
 * limit, a full device) leaves the old file byte-identical and no temporary
 * file, a good one replaces it. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fileio.h"
#include "trk_test.h"

/* A temporary file with n bytes of a known pattern; its path in path[]. */
static void make_file(char path[64], size_t n)
{
    const char *dir = getenv("TMPDIR");
    snprintf(path, 64, "%.40s/trk_test_fileio_XXXXXX", dir ? dir : "/tmp");
    const int fd = mkstemp(path);
    assert_true(fd >= 0);
    FILE *f = fdopen(fd, "wb");
    assert_non_null(f);
    for (size_t i = 0; i < n; i++) fputc((int)((i * 131 + i / 251) & 0xff), f);
    assert_int_equal(fclose(f), 0);
}

static void test_sizes(void **state)
{
    (void)state;
    /* around the first buffer (64 KiB, one byte kept for the NUL) and its doublings */
    const size_t sizes[] = {0, 1, 65534, 65535, 65536, 65537, 131071, 131072, 300000};
    for (size_t k = 0; k < sizeof sizes / sizeof sizes[0]; k++) {
        char path[64];
        make_file(path, sizes[k]);
        size_t len = 12345;
        unsigned char *b = fileio_read(path, &len);
        assert_non_null(b);
        assert_int_equal(len, sizes[k]);
        for (size_t i = 0; i < len; i++)
            if (b[i] != (unsigned char)((i * 131 + i / 251) & 0xff)) fail_msg("byte %zu of %zu differs", i, len);
        assert_int_equal(b[len], 0);
        free(b);
        remove(path);
    }
}

static void test_missing(void **state)
{
    (void)state;
    size_t len = 7;
    errno = 0;
    assert_null(fileio_read("/nonexistent/trk_test_fileio", &len));
    assert_int_equal(errno, ENOENT);
    assert_int_equal(len, 0);
}

static void test_read_bound(void **state)
{
    (void)state;
    size_t len = 5;
    errno = 0;
    assert_null(fileio_read_max("/dev/zero", 100000, &len)); /* endless: refused after the bound */
    assert_int_equal(errno, EFBIG);
    assert_int_equal(len, 0);
    char path[64];
    make_file(path, 70000);
    unsigned char *b = fileio_read_max(path, 70000, &len); /* exactly the bound: read */
    assert_non_null(b);
    assert_int_equal(len, 70000);
    free(b);
    errno = 0;
    assert_null(fileio_read_max(path, 69999, &len));
    assert_int_equal(errno, EFBIG);
    assert_null(fileio_read_max(path, 0, &len));
    remove(path);
}

/* Whole contents of path into buf (at most cap bytes): the count. */
static size_t slurp(const char *path, unsigned char *buf, size_t cap)
{
    FILE *f = fopen(path, "rb");
    assert_non_null(f);
    const size_t n = fread(buf, 1, cap, f);
    fclose(f);
    return n;
}

/* Files in dir whose name starts with prefix. */
static int count_prefixed(const char *dir, const char *prefix)
{
    DIR *d = opendir(dir);
    assert_non_null(d);
    int n = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;) n += strncmp(e->d_name, prefix, strlen(prefix)) == 0;
    closedir(d);
    return n;
}

static void test_atomic_replace(void **state)
{
    (void)state;
    char path[64];
    make_file(path, 3000); /* the "valid old table" */
    static unsigned char old[4096], now[70000], big[70000];
    const size_t n_old = slurp(path, old, sizeof old);
    assert_int_equal(n_old, 3000);
    const char *slash = strrchr(path, '/');
    char dir[64];
    snprintf(dir, sizeof dir, "%.*s", (int)(slash - path), path);
    for (size_t i = 0; i < sizeof big; i++) big[i] = (unsigned char)(i * 7);

    /* a failed regeneration: writes beyond 16 KiB fail (EFBIG, as on a full disk) */
    struct rlimit saved, small;
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &saved), 0);
    small = saved;
    small.rlim_cur = 16384;
    void (*prev)(int) = signal(SIGXFSZ, SIG_IGN);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &small), 0);
    errno = 0;
    const int rc_write = fileio_write(path, big, sizeof big);
    const int e_write = errno;
    struct fileio_out o;
    FILE *f = fileio_create(&o, path, 0);
    int rc_text = -2, e_text = 0;
    if (f) {
        for (int i = 0; i < 5000; i++) fprintf(f, "line %d of a CSV that does not fit\n", i);
        rc_text = fileio_commit(&o);
        e_text = errno;
    }
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &saved), 0);
    signal(SIGXFSZ, prev);
    assert_int_equal(rc_write, -1);
    assert_int_equal(e_write, EFBIG);
    assert_non_null(f);
    assert_int_equal(rc_text, -1);
    assert_true(e_text != 0);
    size_t n = slurp(path, now, sizeof now);
    assert_int_equal(n, n_old);
    assert_memory_equal(now, old, n_old); /* byte-identical */
    assert_int_equal(count_prefixed(dir, strrchr(path, '/') + 1), 1); /* no PATH.tmp-* left */

    /* a discarded output leaves it too */
    assert_non_null(fileio_create(&o, path, 1));
    fputs("half", o.f);
    fileio_discard(&o);
    fileio_discard(&o); /* twice: harmless */
    assert_int_equal(slurp(path, now, sizeof now), n_old);
    assert_int_equal(count_prefixed(dir, strrchr(path, '/') + 1), 1);

    /* a good write replaces it, with fopen's permissions */
    assert_int_equal(fileio_write(path, big, sizeof big), 0);
    n = slurp(path, now, sizeof now);
    assert_int_equal(n, sizeof big);
    assert_memory_equal(now, big, sizeof big);
    struct stat st;
    assert_int_equal(stat(path, &st), 0);
    const mode_t um = umask(0);
    umask(um);
    assert_int_equal(st.st_mode & 0777, 0666 & ~um);
    assert_int_equal(count_prefixed(dir, strrchr(path, '/') + 1), 1);
    remove(path);
}

static void test_device_in_place(void **state)
{
    (void)state;
    /* /dev/full is written in place (no temporary file in /dev, no rename over the device) and
     * the failure reported */
    static unsigned char b[100];
    errno = 0;
    assert_int_equal(fileio_write("/dev/full", b, sizeof b), -1);
    assert_int_equal(errno, ENOSPC);
    struct fileio_out o;
    assert_non_null(fileio_create(&o, "/dev/full", 0));
    assert_int_equal(o.in_place, 1);
    fprintf(o.f, "x\n");
    errno = 0;
    assert_int_equal(fileio_commit(&o), -1);
    assert_int_equal(errno, ENOSPC);
    struct stat st;
    assert_int_equal(stat("/dev/full", &st), 0);
    assert_true(S_ISCHR(st.st_mode));
    assert_int_equal(count_prefixed("/dev", "full.tmp-"), 0);
    /* a write that fails at once (more than the stream's buffer): its own
     * errno, not EIO */
    static unsigned char big[1 << 20];
    assert_non_null(fileio_create(&o, "/dev/full", 1));
    assert_int_equal(fileio_put(&o, big, sizeof big), -1);
    assert_int_equal(errno, ENOSPC);
    assert_int_equal(fileio_put(&o, b, 1), -1); /* nothing more after a failure */
    errno = 0;
    assert_int_equal(fileio_commit(&o), -1);
    assert_int_equal(errno, ENOSPC);
    /* /dev/null: written in place, success */
    assert_int_equal(fileio_write("/dev/null", b, sizeof b), 0);
    /* a directory that does not exist: NULL with errno */
    errno = 0;
    assert_null(fileio_create(&o, "/nonexistent/dir/file", 0));
    assert_int_equal(errno, ENOENT);
    fileio_discard(&o);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sizes),
        cmocka_unit_test(test_missing),
        cmocka_unit_test(test_read_bound),
        cmocka_unit_test(test_atomic_replace),
        cmocka_unit_test(test_device_in_place),
    };
    return trk_run_tests("fileio", tests, NULL, NULL);
}
