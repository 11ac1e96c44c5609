# trk-lcm-bridge: liblcm (transport, log files are read/written without it).
TOOL_LDLIBS_trk-lcm-bridge := $(or $(shell pkg-config --libs lcm 2>/dev/null),-llcm)
