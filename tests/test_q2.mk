# tests/test_q2.mk - test_q2 checks that the q2 sampler gives the same bits with
# 1 and 2 threads: libtrk_tools.a holds the OpenMP build of q2_is.c (mk/q2.mk)
# and every host program links -fopenmp; nothing to add here.
