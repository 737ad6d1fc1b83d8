## nexys_a7.xdc: the pins nexys_a7_top uses on the Digilent Nexys A7-100T (XC7A100T-1CSG324C).
## Package pins and I/O standards from Digilent's master file Nexys-A7-100T-Master.xdc
## (github.com/Digilent/digilent-xdc); only the ports used here, with that file's port names.
## All pins used are in 3.3 V banks (LVCMOS33).

## Clock: the 100 MHz oscillator
set_property -dict { PACKAGE_PIN E3  IOSTANDARD LVCMOS33 } [get_ports CLK100MHZ]; #IO_L12P_T1_MRCC_35
create_clock -add -name sys_clk_pin -period 10.00 -waveform {0 5} [get_ports CLK100MHZ]

## The MMCM's two outputs (digilent_clocks: CLKOUT0 = clk_sys, CLKOUT1 = clk_pix) are derived by
## Vivado automatically from sys_clk_pin. They are related (one VCO), but the design never relies on
## that: every signal from one to the other goes through a synchroniser of soc_top/gpu_top
## (gpu_cdc_sync: two flops for the reset and the front-bank select, which changes only in vertical
## blank; gpu_cdc_pulse: a toggle for vblank_start) or through a dual-clock memory: the
## framebuffer's block RAMs (the back bank written on clk_sys, the front bank read on clk_pix) and
## the palette's LUT RAM (written on clk_sys, read on clk_pix without a handshake: a write during the
## visible area may show one wrong colour for one pixel, accepted in gpu_top's header). So the two
## domains are declared asynchronous, and Vivado times each one alone.
set_clock_groups -name sys_pix_async -asynchronous \
    -group [get_clocks -of_objects [get_pins -hierarchical -filter {NAME =~ *u_clocks/u_mmcm/CLKOUT0}]] \
    -group [get_clocks -of_objects [get_pins -hierarchical -filter {NAME =~ *u_clocks/u_mmcm/CLKOUT1}]]

## Reset: the red CPU RESET button, active LOW
set_property -dict { PACKAGE_PIN C12 IOSTANDARD LVCMOS33 } [get_ports CPU_RESETN]; #IO_L3P_T0_DQS_AD1P_15

## USB-RS232 (FT2232HQ), named from the bridge's side: UART_TXD_IN into the FPGA, UART_RXD_OUT out
set_property -dict { PACKAGE_PIN C4  IOSTANDARD LVCMOS33 } [get_ports UART_TXD_IN];  #IO_L7P_T1_AD6P_35
set_property -dict { PACKAGE_PIN D4  IOSTANDARD LVCMOS33 } [get_ports UART_RXD_OUT]; #IO_L11N_T1_SRCC_35

## LEDs
set_property -dict { PACKAGE_PIN H17 IOSTANDARD LVCMOS33 } [get_ports {LED[0]}]
set_property -dict { PACKAGE_PIN K15 IOSTANDARD LVCMOS33 } [get_ports {LED[1]}]
set_property -dict { PACKAGE_PIN J13 IOSTANDARD LVCMOS33 } [get_ports {LED[2]}]
set_property -dict { PACKAGE_PIN N14 IOSTANDARD LVCMOS33 } [get_ports {LED[3]}]
set_property -dict { PACKAGE_PIN R18 IOSTANDARD LVCMOS33 } [get_ports {LED[4]}]
set_property -dict { PACKAGE_PIN V17 IOSTANDARD LVCMOS33 } [get_ports {LED[5]}]
set_property -dict { PACKAGE_PIN U17 IOSTANDARD LVCMOS33 } [get_ports {LED[6]}]
set_property -dict { PACKAGE_PIN U16 IOSTANDARD LVCMOS33 } [get_ports {LED[7]}]
set_property -dict { PACKAGE_PIN V16 IOSTANDARD LVCMOS33 } [get_ports {LED[8]}]
set_property -dict { PACKAGE_PIN T15 IOSTANDARD LVCMOS33 } [get_ports {LED[9]}]
set_property -dict { PACKAGE_PIN U14 IOSTANDARD LVCMOS33 } [get_ports {LED[10]}]
set_property -dict { PACKAGE_PIN T16 IOSTANDARD LVCMOS33 } [get_ports {LED[11]}]
set_property -dict { PACKAGE_PIN V15 IOSTANDARD LVCMOS33 } [get_ports {LED[12]}]
set_property -dict { PACKAGE_PIN V14 IOSTANDARD LVCMOS33 } [get_ports {LED[13]}]
set_property -dict { PACKAGE_PIN V12 IOSTANDARD LVCMOS33 } [get_ports {LED[14]}]
set_property -dict { PACKAGE_PIN V11 IOSTANDARD LVCMOS33 } [get_ports {LED[15]}]

## VGA connector (4 bits per colour)
set_property -dict { PACKAGE_PIN A3  IOSTANDARD LVCMOS33 } [get_ports {VGA_R[0]}]
set_property -dict { PACKAGE_PIN B4  IOSTANDARD LVCMOS33 } [get_ports {VGA_R[1]}]
set_property -dict { PACKAGE_PIN C5  IOSTANDARD LVCMOS33 } [get_ports {VGA_R[2]}]
set_property -dict { PACKAGE_PIN A4  IOSTANDARD LVCMOS33 } [get_ports {VGA_R[3]}]
set_property -dict { PACKAGE_PIN C6  IOSTANDARD LVCMOS33 } [get_ports {VGA_G[0]}]
set_property -dict { PACKAGE_PIN A5  IOSTANDARD LVCMOS33 } [get_ports {VGA_G[1]}]
set_property -dict { PACKAGE_PIN B6  IOSTANDARD LVCMOS33 } [get_ports {VGA_G[2]}]
set_property -dict { PACKAGE_PIN A6  IOSTANDARD LVCMOS33 } [get_ports {VGA_G[3]}]
set_property -dict { PACKAGE_PIN B7  IOSTANDARD LVCMOS33 } [get_ports {VGA_B[0]}]
set_property -dict { PACKAGE_PIN C7  IOSTANDARD LVCMOS33 } [get_ports {VGA_B[1]}]
set_property -dict { PACKAGE_PIN D7  IOSTANDARD LVCMOS33 } [get_ports {VGA_B[2]}]
set_property -dict { PACKAGE_PIN D8  IOSTANDARD LVCMOS33 } [get_ports {VGA_B[3]}]
set_property -dict { PACKAGE_PIN B11 IOSTANDARD LVCMOS33 } [get_ports VGA_HS]
set_property -dict { PACKAGE_PIN B12 IOSTANDARD LVCMOS33 } [get_ports VGA_VS]

## The button, the UART and the LEDs are asynchronous to every clock (each input has a two-flop
## synchroniser in soc_top / soc_uart; the LEDs are seen by eye); the VGA outputs leave from one
## clk_pix register each into a resistor ladder and a monitor that recovers its own pixel clock.
## None has an external timing relation worth constraining, so none is timed.
set_false_path -from [get_ports {CPU_RESETN UART_TXD_IN}]
set_false_path -to [get_ports {UART_RXD_OUT LED[*] VGA_R[*] VGA_G[*] VGA_B[*] VGA_HS VGA_VS}]

## Configuration (the master file has none for this board; the usual for a 3.3 V bank 0)
set_property CONFIG_VOLTAGE 3.3 [current_design]
set_property CFGBVS VCCO [current_design]
