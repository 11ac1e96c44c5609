# mk/q2.mk - the q2 importance sampler (tools/gen/q2_is.c) and the
# amplitude table generator (tools/gen/amp_table.c) with OpenMP.
#
# Both are compiled once, with -fopenmp, into libtrk_gen.a (tools/gen); every host
# program links with -fopenmp (LDFLAGS_ALL in the Makefile), so a program that
# calls them runs on all cores (OMP_NUM_THREADS or the tools' --threads to
# choose). Their results are bit-identical for any thread count (q2_is.h,
# amp_table.h; checked by test_q2, q2-repro and sim-papers-repro). The
# firmware image (mk/qemu.mk) compiles amp_table.c for the target without
# OpenMP: its pragmas sit under #ifdef _OPENMP.
#
# The sampler is compiled at -O3 (vectorised inner loops; -fno-trapping-math
# lets the compiler turn the selects of q2_fastmath.h into blends, it changes
# no result); FP contraction is off so that no FMA changes the bits between
# the AVX2 and baseline clones of the kernels. Sanitizer builds keep their
# OPT (-O1): the -O3 compile of q2_is.c costs ~20 s there and checks nothing
# more.
Q2_IS_FLAGS := $(if $(filter 1,$(SAN)),,-O3) -ffp-contract=off -fno-trapping-math
$(BUILD)/obj/tools/gen/q2_is.o: CFLAGS_ALL += $(Q2_IS_FLAGS) -fopenmp
$(BUILD)/obj/tools/gen/q2_amp.o: CFLAGS_ALL += $(Q2_IS_FLAGS)
$(BUILD)/obj/tools/gen/amp_table.o: CFLAGS_ALL += -fopenmp
