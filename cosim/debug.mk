# cosim/debug.mk — `make debug [SCENE=…]`: the firmware under gdb-multiarch, halted at main with its
# symbols, while the GPU is co-simulated as in `make run` (cosim/debug.sh, cosim/debug.gdb); included
# by the top-level Makefile after GPUSIM and FW_ELF are defined.
#
#   DEBUG_PORT=N   QEMU's GDB stub on this TCP port (default: a free one)
#   UART_PTY=LINK  the firmware's UART also on a pseudo-terminal, as with `make run`
# The harness's output (the firmware's UART, errors) goes to $(OUT)/debug-cosim.log, its frames to
# $(OUT)/frames; quitting gdb ends the co-simulation.
DEBUG_PORT ?=

.PHONY: debug
debug: $(FW_ELF) $(GPUSIM)
	@DEBUG_PORT=$(DEBUG_PORT) bash cosim/debug.sh $(GPUSIM) $(FW_ELF) $(OUT) \
	  $(if $(UART_PTY),--uart-pty $(UART_PTY))
