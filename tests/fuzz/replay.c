/* replay.c - run a libFuzzer target over files without libFuzzer (gcc or
 * clang, any sanitizer): each argument is a file or a directory of files;
 * each file is read into a buffer of exactly its size (so that an over-read
 * by one byte is caught by ASan) and passed to LLVMFuzzerTestOneInput.
 * Used by make test (mk/fuzz.mk: fuzz-replay) to replay the committed corpus
 * tests/fuzz/corpus/<target>/ and by hand to reproduce a finding. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static long n_inputs;

static int replay_file(const char *path)
{
    FILE *fp = fopen(path, "rb");
    if (!fp) {
        fprintf(stderr, "replay: cannot open %s\n", path);
        return 1;
    }
    struct stat st;
    if (fstat(fileno(fp), &st) != 0 || st.st_size < 0) {
        fclose(fp);
        fprintf(stderr, "replay: cannot stat %s\n", path);
        return 1;
    }
    size_t n = (size_t)st.st_size;
    uint8_t *buf = malloc(n ? n : 1);
    if (!buf || fread(buf, 1, n, fp) != n) {
        free(buf);
        fclose(fp);
        fprintf(stderr, "replay: cannot read %s\n", path);
        return 1;
    }
    fclose(fp);
    if (n == 0) { /* exactly sized: nothing to read */
        free(buf);
        buf = NULL;
    }
    LLVMFuzzerTestOneInput(buf, n);
    free(buf);
    n_inputs++;
    return 0;
}

static int replay_path(const char *path)
{
    struct stat st;
    if (stat(path, &st) != 0) {
        fprintf(stderr, "replay: no such file or directory: %s\n", path);
        return 1;
    }
    if (!S_ISDIR(st.st_mode)) return replay_file(path);
    DIR *d = opendir(path);
    if (!d) return 1;
    int bad = 0;
    struct dirent *e;
    while ((e = readdir(d)) != NULL) {
        if (e->d_name[0] == '.') continue;
        size_t len = strlen(path) + strlen(e->d_name) + 2;
        char *p = malloc(len);
        if (!p) {
            bad = 1;
            break;
        }
        snprintf(p, len, "%s/%s", path, e->d_name);
        bad |= replay_path(p);
        free(p);
    }
    closedir(d);
    return bad;
}

int main(int argc, char **argv)
{
    int bad = 0;
    if (argc < 2) {
        fprintf(stderr, "usage: %s FILE|DIR...\n", argv[0]);
        return 2;
    }
    for (int a = 1; a < argc; a++) bad |= replay_path(argv[a]);
    printf("replay %s: %ld inputs%s\n", argv[0], n_inputs, bad ? ", some unreadable" : "");
    return bad || n_inputs == 0;
}
