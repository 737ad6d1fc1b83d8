# cosim/debug.gdb — `make debug`'s commands once gdb is connected to QEMU's GDB stub (cosim/debug.sh):
# the firmware is halted at reset; run it to main, with the ELF's symbols loaded.
break main
continue
