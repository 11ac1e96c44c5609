# tests/test_q2.mk - test_q2 checks that the q2 sampler gives the same bits with
# 1 and 2 threads, so it links the OpenMP build of tools/common/q2_is.c
# (rule in mk/q2.mk) ahead of libtrk_tools.a.
$(BUILD)/tests/test_q2: $(BUILD)/obj/omp/tools/common/q2_is.o
TEST_EXTRA_OBJS_test_q2 += $(BUILD)/obj/omp/tools/common/q2_is.o
TEST_LDLIBS_test_q2 += -fopenmp
