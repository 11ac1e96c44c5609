# mk/mpi.mk - the work distribution layer (tools/par, issue 20).
#
# tools/par/*.c (libtrk_par.a) runs batches of work units on OpenMP threads,
# so it is compiled with -fopenmp (every host program links it).
$(BUILD)/obj/tools/par/%.o: CFLAGS_ALL += -fopenmp
