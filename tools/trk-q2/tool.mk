# tools/trk-q2/tool.mk - trk-q2 runs the q2 sampler on all cores: it links the
# OpenMP build of tools/common/q2_is.c (rule in mk/q2.mk) ahead of libtrk_tools.a.
TOOL_DEPS_trk-q2 += $(BUILD)/obj/omp/tools/common/q2_is.o
TOOL_LDLIBS_trk-q2 += -fopenmp
