/* test_fileio.c - fileio_read (tools/cli/fileio.h): whole files of any
 * size byte for byte with a NUL after them, empty files, and a missing file
 * (NULL, errno from fopen, length 0). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
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

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_sizes),
        cmocka_unit_test(test_missing),
    };
    return trk_run_tests("fileio", tests, NULL, NULL);
}
