# test_lcm.mk - the LCM bridge's tests (tests/test_lcm_*.c).
# Their objects include lcm-gen headers (mk/lcm.mk generates them; tests/*.mk
# are read before mk/*.mk, so the stamp is named literally). test_lcm_bridge
# and test_lcm_polar run the bridge core and its LCM transport (libtrk_lcm.a:
# memq round trips, log replay) and so link liblcm.
LCM_TEST_OBJS := $(patsubst tests/%.c,$(BUILD)/obj/tests/%.o,$(wildcard tests/test_lcm_*.c))
$(LCM_TEST_OBJS): $(BUILD)/gen/lcm/.stamp
TEST_LDLIBS_test_lcm_bridge := $(or $(shell pkg-config --libs lcm 2>/dev/null),-llcm)
TEST_LDLIBS_test_lcm_polar := $(TEST_LDLIBS_test_lcm_bridge)
