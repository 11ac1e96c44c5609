# mk/q2.mk - the q2 importance sampler (tools/common/q2_is.c) with OpenMP.
#
# tools/common/q2_is.c is compiled twice:
#   $(BUILD)/obj/tools/common/q2_is.o      serial, in libtrk_tools.a (generic rule;
#                                          its OpenMP pragmas are macros that vanish)
#   $(BUILD)/obj/omp/tools/common/q2_is.o  with -fopenmp (rule below)
# A program that wants threads links the second object before libtrk_tools.a
# (the archive member is then never pulled) and links with -fopenmp:
#   tools/trk-NAME/tool.mk:  TOOL_DEPS_trk-NAME += $(BUILD)/obj/omp/tools/common/q2_is.o
#                            TOOL_LDLIBS_trk-NAME += -fopenmp
#   tests/NAME.mk:           $(BUILD)/tests/test_NAME: $(BUILD)/obj/omp/tools/common/q2_is.o
#                            TEST_EXTRA_OBJS_test_NAME += $(BUILD)/obj/omp/tools/common/q2_is.o
#                            TEST_LDLIBS_test_NAME += -fopenmp
# Both objects give bit-identical results (q2_is.h). The sampler is compiled
# at -O3 (vectorised inner loops; -fno-trapping-math lets the compiler turn
# the selects of q2_fastmath.h into blends, it changes no result); FP
# contraction is off so that no FMA changes the bits between the AVX2 and
# baseline clones of the kernels.
Q2_IS_OMP_OBJ := $(BUILD)/obj/omp/tools/common/q2_is.o
Q2_IS_FLAGS := -O3 -ffp-contract=off -fno-trapping-math

$(Q2_IS_OMP_OBJ): tools/common/q2_is.c
	@mkdir -p $(@D)
	$(CC) $(CFLAGS_ALL) $(Q2_IS_FLAGS) -fopenmp -Itools/common -c $< -o $@

$(BUILD)/obj/tools/common/q2_is.o: CFLAGS_ALL += $(Q2_IS_FLAGS)
$(BUILD)/obj/tools/common/q2_amp.o: CFLAGS_ALL += $(Q2_IS_FLAGS)
