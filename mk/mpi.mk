# mk/mpi.mk - the work distribution layer (tools/par) and the MPI
# builds of trk-tablegen and trk-sim.
#
# tools/par/*.c (libtrk_par.a) runs batches of work units on OpenMP threads,
# so it is compiled with -fopenmp (every host program links it). Its MPI
# layer tools/par/mpi/*.c and the MPI builds of the two tools are compiled
# with mpicc and -DTRK_TOOL_MPI into $(BUILD)/obj-mpi/:
#   $(BUILD)/bin/trk-tablegen-mpi, $(BUILD)/bin/trk-sim-mpi
# the same sources as the single-process tools (which stay as they are),
# plus --checkpoint FILE and --checkpoint-interval S. Built by `make` when
# mpicc is found (MPI=1 forces them, MPI=0 leaves them out); mpicc runs this
# build's compiler (OMPI_CC, MPICH_CC). libtrk never sees MPI.
#
# The steps of `make test` (default configuration; skipped with a message
# without mpicc), tests/mpi_steps.sh: mpi-tablegen and mpi-sim (q2 and
# amplitude tables, trk-sim experiments: the bytes of `mpirun -np 3` with 1
# and 2 threads per rank against the single-process tools) and mpi-resume
# (a rank that fails halfway, a rank killed: the job fails with a message
# and no output file; resumed from the checkpoint, the same bytes).
$(BUILD)/obj/tools/par/%.o: CFLAGS_ALL += -fopenmp

MPICC ?= mpicc
MPI ?= $(if $(shell command -v $(MPICC) 2>/dev/null),1,0)
MPI_TOOL_NAMES := trk-tablegen trk-sim
MPI_BINS := $(addprefix $(BUILD)/bin/,$(addsuffix -mpi,$(MPI_TOOL_NAMES)))
MPI_OBJ = $(patsubst %.c,$(BUILD)/obj-mpi/%.o,$(1))
PARMPI_LIB := $(BUILD)/libtrk_par_mpi.a
# mpicc with this build's compiler underneath (Open MPI reads OMPI_CC, MPICH MPICH_CC)
MPICC_RUN := OMPI_CC='$(CC)' MPICH_CC='$(CC)' $(MPICC)

ifeq ($(MPI),1)
tools: $(MPI_BINS)
# installed by a double build, as the other tools (a float build installs
# none: Makefile "install")
ifneq ($(REAL),float)
install: $(MPI_BINS)
INSTALL_EXTRA += install -m 755 $(MPI_BINS) $(DESTDIR)$(PREFIX)/bin/ ;
endif

$(BUILD)/obj-mpi/tools/%.o: tools/%.c $(BUILD_CONFIG)
	@mkdir -p $(@D)
	$(call say,MPCC,$<)
	$(Q)$(MPICC_RUN) $(CFLAGS_ALL) -fopenmp -DTRK_TOOL_MPI $(TOOL_INC) -Itools/par/mpi -I$(GEN) \
	  $(TOOL_CFLAGS_$(firstword $(subst /, ,$*))) -c $< -o $@
$(PARMPI_LIB): $(call MPI_OBJ,$(wildcard tools/par/mpi/*.c))
	$(archive)
$(BUILD)/obj-mpi/tools/trk-tablegen/main.o: $(GEN)/tablegen_cmds.inc
$(BUILD)/obj-mpi/tools/trk-sim/main.o: $(GEN)/sim_experiments.inc

define MPI_TOOL_template
$(BUILD)/bin/$(1)-mpi: $$(call MPI_OBJ,$$(wildcard tools/$(1)/*.c)) $$(TOOL_DEPS_$(1)) $(PARMPI_LIB) $(TOOL_LIBS)
	@mkdir -p $$(@D)
	$$(call say,LD,$$@)
	$$(Q)$(MPICC_RUN) $$(LDFLAGS_ALL) $$(TOOL_LDFLAGS_$(1)) $$(filter %.o,$$^) $(PARMPI_LIB) $(TOOL_LIBS) \
	  $$(TOOL_LDLIBS_$(1)) -lm -o $$@
endef
$(foreach t,$(MPI_TOOL_NAMES),$(eval $(call MPI_TOOL_template,$(t))))

-include $(shell find $(BUILD)/obj-mpi -name '*.d' 2>/dev/null)
endif

# --- the steps of `make test` (tests/mpi_steps.sh; without mpicc: skipped,
# with a message)
MPI_STEPS := mpi-tablegen mpi-sim mpi-resume
TEST_EXTRA += $(MPI_STEPS)
ifeq ($(MPI),1)
$(foreach s,$(MPI_STEPS),$(eval TEST_EXTRA_DEPS_$(s) := $(MPI_BINS) $(BUILD)/bin/trk-tablegen $(BUILD)/bin/trk-sim))
endif
.PHONY: $(MPI_STEPS)
$(MPI_STEPS): %: $(TEST_EXTRA_DEPS_mpi-tablegen)
	@if [ '$(MPI)' = 1 ]; then sh tests/mpi_steps.sh $(patsubst mpi-%,%,$@) $(BUILD)/bin; \
	 else echo "$@: no $(MPICC) (MPI=0): the MPI builds and their checks are skipped"; fi
