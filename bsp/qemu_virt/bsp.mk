# bsp/qemu_virt/bsp.mk — what firmware/firmware.mk needs to build for QEMU `virt` (riscv32).
# A new platform provides the same variables in bsp/<platform>/bsp.mk.

FW_CC         = $(RV_CC)
FW_OBJDUMP    = $(patsubst %gcc,%objdump,$(RV_CC))
FW_ARCH_FLAGS = -march=rv32im -misa-spec=2.2 -mabi=ilp32 -mcmodel=medany --specs=picolibc.specs \
                -DPICOLIBC_INTEGER_PRINTF_SCANF
FW_BSP_SRCS   = $(wildcard bsp/qemu_virt/*.c) $(wildcard bsp/rv32/*.c)
FW_LDSCRIPT   = linker/qemu_virt.ld
# crt0 "hosted" calls exit(main()); the BSP's _exit() ends QEMU through sifive_test.
FW_BSP_LDFLAGS = --crt0=hosted -Wl,--no-warn-rwx-segments

# How to run an ELF: append `-kernel ELF`. -icount shift=0 makes minstret exact.
FW_RUN        = qemu-system-riscv32 -machine virt -bios none -display none -serial stdio \
                -monitor none -icount shift=0
