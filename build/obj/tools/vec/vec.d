build/obj/tools/vec/vec.o: tools/vec/vec.c tools/vec/vec.h
tools/vec/vec.h:
