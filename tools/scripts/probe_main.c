/* probe_main.c - the smallest program to link a whole libtrk.a with the
 * target's C library (mk/size.mk): the linked image's disassembly gives the
 * stack depth of the libm/libc functions libtrk calls. Never run. */
int main(void);
int main(void) { return 0; }
