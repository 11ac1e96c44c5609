TOOL_LDLIBS_trk-bench += -fopenmp

# The LCM bridge benchmarks (bench_lcm.c): the bridge's core and LCM
# transport objects (tools/trk-lcm-bridge, not its main.o) and liblcm.
TOOL_DEPS_trk-bench += $(BUILD)/obj/tools/trk-lcm-bridge/bridge.o $(BUILD)/obj/tools/trk-lcm-bridge/transport.o
TOOL_LDLIBS_trk-bench += -llcm
