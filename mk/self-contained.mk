# mk/self-contained.mk - `make self-contained`: no tracked file names a path
# outside the repository (tests/self_contained.sh), a step of `make test`.
TEST_EXTRA += self-contained
TEST_EXTRA_DEPS_self-contained :=
.PHONY: self-contained
self-contained:
	@sh tests/self_contained.sh .
