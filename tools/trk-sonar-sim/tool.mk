# trk-sonar-sim: liblcm (publishing; --log writes the file without it).
TOOL_LDLIBS_trk-sonar-sim := $(or $(shell pkg-config --libs lcm 2>/dev/null),-llcm)
