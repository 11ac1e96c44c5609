# mk/lcm_java.mk - trk's LCM message types for Java, and lcm-spy that starts
# (docs/lcm.md "Watching the channels: make spy").
#
#   make java        $(BUILD)/java/trk_lcm.jar: lcm-gen -j of tools/lcm/types,
#                    compiled against liblcm-java's lcm.jar (javac, jar: a JDK)
#   make spy         lcm-spy with trk's types (tools/lcm/java/trk-lcm-spy: no
#                    -Xincgc, jchart2d.jar on the class path); SPY_URL=URL
#                    chooses the transport (default $LCM_DEFAULT_URL, else
#                    LCM's), e.g. make spy SPY_URL='file://$(abspath
#                    build/demo-lcm/tracks.lcmlog)?speed=10'
#   make test-lcm-spy  a step of `make test` (tests/lcm_spy.sh): lcm-spy under
#                    Xvfb on a log with trk's four channels; skipped with the
#                    reason without a JDK, liblcm-java, libjchart2d-java or xvfb
#   make install     also installs the jar to $(PREFIX)/share/java/trk_lcm.jar
#                    and the launcher to $(PREFIX)/bin/trk-lcm-spy (when javac
#                    and lcm.jar are there; a note otherwise)
LCM_JAVA_LIB ?= /usr/share/java/lcm.jar
LCM_JAVA_DIR := $(BUILD)/java
LCM_JAR := $(LCM_JAVA_DIR)/trk_lcm.jar
SPY_CHECK_JAR := $(LCM_JAVA_DIR)/trk_spy_check.jar
SPY_URL ?=
# 1 when the jars can be built here (the steps below then have them built
# first, once, by the make that runs the steps: no two steps build them)
HAVE_JAVA := $(shell command -v javac > /dev/null 2>&1 && command -v jar > /dev/null 2>&1 && \
  test -f $(LCM_JAVA_LIB) && echo 1)
.PHONY: java spy test-lcm-spy

define java_needs
	@command -v javac > /dev/null 2>&1 && command -v jar > /dev/null 2>&1 || \
	  { echo "javac/jar not found: apt-get install default-jdk-headless"; exit 1; }
	@test -f $(LCM_JAVA_LIB) || { echo "$(LCM_JAVA_LIB) not found: apt-get install liblcm-java"; exit 1; }
endef

java: $(LCM_JAR)
$(LCM_JAR): $(LCM_FILES) mk/lcm_java.mk
	$(java_needs)
	@rm -rf $(LCM_JAVA_DIR)/src $(LCM_JAVA_DIR)/classes && mkdir -p $(LCM_JAVA_DIR)/src $(LCM_JAVA_DIR)/classes
	$(call say,GEN,$(LCM_JAVA_DIR)/src (lcm-gen -j))
	$(Q)lcm-gen -j --jpath $(LCM_JAVA_DIR)/src $(LCM_FILES) > /dev/null
	@for t in $(patsubst $(LCM_DIR)/%.lcm,%,$(LCM_FILES)); do \
	  test -s $(LCM_JAVA_DIR)/src/trk/$$t.java || { echo "lcm-gen did not write $(LCM_JAVA_DIR)/src/trk/$$t.java"; exit 1; }; done
	$(call say,JAVA,$@)
	$(Q)javac -nowarn --release 8 -Xlint:-options -cp $(LCM_JAVA_LIB) -d $(LCM_JAVA_DIR)/classes $(LCM_JAVA_DIR)/src/trk/*.java
	$(Q)rm -f $@ && jar cf $@ -C $(LCM_JAVA_DIR)/classes .

$(SPY_CHECK_JAR): tools/lcm/java/TrkSpyCheck.java $(LCM_JAR)
	$(java_needs)
	@rm -rf $(LCM_JAVA_DIR)/check && mkdir -p $(LCM_JAVA_DIR)/check
	$(call say,JAVA,$@)
	$(Q)javac -nowarn --release 8 -Xlint:-options -cp $(LCM_JAVA_LIB):$(LCM_JAR) -d $(LCM_JAVA_DIR)/check $<
	$(Q)rm -f $@ && jar cf $@ -C $(LCM_JAVA_DIR)/check .

spy: $(LCM_JAR)
	TRK_LCM_JAR=$(LCM_JAR) sh tools/lcm/java/trk-lcm-spy $(if $(SPY_URL),-l '$(SPY_URL)')

TEST_EXTRA += test-lcm-spy
TEST_EXTRA_DEPS_test-lcm-spy := $(BUILD)/bin/trk-sonar-sim $(BUILD)/bin/trk-lcm-bridge $(BUILD)/bin/trk-tablegen \
  $(if $(HAVE_JAVA),$(LCM_JAR) $(SPY_CHECK_JAR))
test-lcm-spy: $(TEST_EXTRA_DEPS_test-lcm-spy)
	@if ! command -v javac > /dev/null 2>&1 || ! command -v jar > /dev/null 2>&1; then \
	  echo "test-lcm-spy: SKIPPED: no javac/jar (apt-get install default-jdk-headless)"; \
	elif [ ! -f $(LCM_JAVA_LIB) ]; then echo "test-lcm-spy: SKIPPED: no $(LCM_JAVA_LIB) (apt-get install liblcm-java)"; \
	else sh tests/lcm_spy.sh $(BUILD) $(LCM_JAR) $(SPY_CHECK_JAR); fi

# --- install: the jar and the launcher (a note when no JDK or lcm.jar)
.PHONY: install-java
install: install-java
# The sub-make has a line of its own: make runs a line that names $(MAKE)
# even under -n, and `make -n install` must install nothing.
JAVA_INSTALLABLE = command -v javac > /dev/null 2>&1 && command -v jar > /dev/null 2>&1 && [ -f $(LCM_JAVA_LIB) ]
install-java:
	@if $(JAVA_INSTALLABLE); then $(MAKE) --no-print-directory $(LCM_JAR); fi
	@if $(JAVA_INSTALLABLE); then \
	  install -d $(DESTDIR)$(PREFIX)/share/java $(DESTDIR)$(PREFIX)/bin && \
	  install -m 644 $(LCM_JAR) $(DESTDIR)$(PREFIX)/share/java/ && \
	  install -m 755 tools/lcm/java/trk-lcm-spy $(DESTDIR)$(PREFIX)/bin/ && \
	  echo "install: $(PREFIX)/share/java/trk_lcm.jar, $(PREFIX)/bin/trk-lcm-spy"; \
	else echo "install: no javac/jar or $(LCM_JAVA_LIB): trk_lcm.jar and trk-lcm-spy not installed"; fi
