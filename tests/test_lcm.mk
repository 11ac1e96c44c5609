# test_lcm.mk - the LCM bridge's tests (tests/test_lcm_*.c).
# Their objects include lcm-gen headers (mk/lcm.mk generates them; tests/*.mk
# are read before mk/*.mk, so the stamp is named literally) and bridge.h.
# test_lcm_bridge links the bridge's transport-free core and its LCM
# transport (memq round trips, log replay) and liblcm.
LCM_TEST_OBJS := $(patsubst tests/%.c,$(BUILD)/obj/tests/%.o,$(wildcard tests/test_lcm_*.c))
$(LCM_TEST_OBJS): $(BUILD)/gen/lcm/.stamp
$(LCM_TEST_OBJS): CFLAGS_ALL += -Itools/trk-lcm-bridge

LCM_BRIDGE_TEST_OBJS := $(BUILD)/obj/tools/trk-lcm-bridge/bridge.o $(BUILD)/obj/tools/trk-lcm-bridge/transport.o
$(BUILD)/tests/test_lcm_bridge: $(LCM_BRIDGE_TEST_OBJS)
TEST_EXTRA_OBJS_test_lcm_bridge := $(LCM_BRIDGE_TEST_OBJS)
TEST_LDLIBS_test_lcm_bridge := $(or $(shell pkg-config --libs lcm 2>/dev/null),-llcm)
