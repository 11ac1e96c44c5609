# mk/example_polar.mk - examples/sonar_polar.c as a `make test` step: a sonar
# on a moving platform (polar scans with the platform's pose, P_D and
# clutter density over range, a coverage sector) holds its near and far
# target with confirmed tracks and confirms no false one (the program's exit
# status says so).
TEST_EXTRA += example-sonar-polar
TEST_EXTRA_DEPS_example-sonar-polar := $(BUILD)/bin/example-sonar_polar
.PHONY: example-sonar-polar
example-sonar-polar: $(TEST_EXTRA_DEPS_example-sonar-polar)
	@out=$$($(BUILD)/bin/example-sonar_polar) || { echo "$$out"; echo "example-sonar-polar: FAILED"; exit 1; }; \
	  echo "$$out" | tail -1
