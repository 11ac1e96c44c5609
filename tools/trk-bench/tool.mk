# tools/trk-bench/tool.mk - the q2 benchmarks (bench_q2.c) time the q2 sampler
# on 1 and 2 threads (libtrk_tools.a holds its OpenMP build, mk/q2.mk).
# The LCM bridge benchmarks (bench_lcm.c): the bridge's core and LCM
# transport objects (tools/trk-lcm-bridge, not its main.o) and liblcm.
TOOL_DEPS_trk-bench += $(BUILD)/obj/tools/trk-lcm-bridge/bridge.o $(BUILD)/obj/tools/trk-lcm-bridge/transport.o
TOOL_LDLIBS_trk-bench += -llcm
