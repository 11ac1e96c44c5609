/* lcm_big_publish.c - publish messages through the LCM C library that its
 * UDP multicast transport must fragment, for the Python receiver's test
 * (tests/python_binding.sh): N messages of SIZE bytes on CHANNEL, byte i of
 * message k being (i * 7 + k) mod 251, then one short message.
 *
 *   py-lcm-big CHANNEL SIZE N */
#define _POSIX_C_SOURCE 200809L
#include <lcm/lcm.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: py-lcm-big CHANNEL SIZE N\n");
        return 2;
    }
    const size_t size = (size_t)atol(argv[2]);
    const int n = atoi(argv[3]);
    lcm_t *lcm = lcm_create(NULL);
    unsigned char *buf = malloc(size ? size : 1);
    if (!lcm || !buf) return 1;
    const struct timespec pause = {0, 50000000};
    for (int k = 0; k < n; k++) {
        for (size_t i = 0; i < size; i++) buf[i] = (unsigned char)((i * 7 + (size_t)k) % 251);
        if (lcm_publish(lcm, argv[1], buf, (unsigned)size) != 0) return 1;
        nanosleep(&pause, NULL);
    }
    const unsigned char done[4] = {'d', 'o', 'n', 'e'};
    if (lcm_publish(lcm, argv[1], done, 4) != 0) return 1;
    free(buf);
    lcm_destroy(lcm);
    return 0;
}
