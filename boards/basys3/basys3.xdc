## basys3.xdc: the pins basys3_top uses on the Digilent Basys3 (rev B/C, XC7A35T-1CPG236C).
## Package pins and I/O standards from Digilent's master file Basys-3-Master.xdc
## (github.com/Digilent/digilent-xdc); only the ports used here, renamed to basys3_top's names as
## that file's header asks. All pins are in 3.3 V banks (LVCMOS33).

## Clock: the 100 MHz oscillator
set_property -dict { PACKAGE_PIN W5  IOSTANDARD LVCMOS33 } [get_ports clk]
create_clock -add -name sys_clk_pin -period 10.00 -waveform {0 5} [get_ports clk]

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

## Reset: the centre button, active high
set_property -dict { PACKAGE_PIN U18 IOSTANDARD LVCMOS33 } [get_ports btnC]

## USB-RS232 (FT2232HQ channel B): RsRx into the FPGA, RsTx out of it
set_property -dict { PACKAGE_PIN B18 IOSTANDARD LVCMOS33 } [get_ports RsRx]
set_property -dict { PACKAGE_PIN A18 IOSTANDARD LVCMOS33 } [get_ports RsTx]

## LEDs
set_property -dict { PACKAGE_PIN U16 IOSTANDARD LVCMOS33 } [get_ports {led[0]}]
set_property -dict { PACKAGE_PIN E19 IOSTANDARD LVCMOS33 } [get_ports {led[1]}]
set_property -dict { PACKAGE_PIN U19 IOSTANDARD LVCMOS33 } [get_ports {led[2]}]
set_property -dict { PACKAGE_PIN V19 IOSTANDARD LVCMOS33 } [get_ports {led[3]}]
set_property -dict { PACKAGE_PIN W18 IOSTANDARD LVCMOS33 } [get_ports {led[4]}]
set_property -dict { PACKAGE_PIN U15 IOSTANDARD LVCMOS33 } [get_ports {led[5]}]
set_property -dict { PACKAGE_PIN U14 IOSTANDARD LVCMOS33 } [get_ports {led[6]}]
set_property -dict { PACKAGE_PIN V14 IOSTANDARD LVCMOS33 } [get_ports {led[7]}]
set_property -dict { PACKAGE_PIN V13 IOSTANDARD LVCMOS33 } [get_ports {led[8]}]
set_property -dict { PACKAGE_PIN V3  IOSTANDARD LVCMOS33 } [get_ports {led[9]}]
set_property -dict { PACKAGE_PIN W3  IOSTANDARD LVCMOS33 } [get_ports {led[10]}]
set_property -dict { PACKAGE_PIN U3  IOSTANDARD LVCMOS33 } [get_ports {led[11]}]
set_property -dict { PACKAGE_PIN P3  IOSTANDARD LVCMOS33 } [get_ports {led[12]}]
set_property -dict { PACKAGE_PIN N3  IOSTANDARD LVCMOS33 } [get_ports {led[13]}]
set_property -dict { PACKAGE_PIN P1  IOSTANDARD LVCMOS33 } [get_ports {led[14]}]
set_property -dict { PACKAGE_PIN L1  IOSTANDARD LVCMOS33 } [get_ports {led[15]}]

## VGA connector (4 bits per colour)
set_property -dict { PACKAGE_PIN G19 IOSTANDARD LVCMOS33 } [get_ports {vgaRed[0]}]
set_property -dict { PACKAGE_PIN H19 IOSTANDARD LVCMOS33 } [get_ports {vgaRed[1]}]
set_property -dict { PACKAGE_PIN J19 IOSTANDARD LVCMOS33 } [get_ports {vgaRed[2]}]
set_property -dict { PACKAGE_PIN N19 IOSTANDARD LVCMOS33 } [get_ports {vgaRed[3]}]
set_property -dict { PACKAGE_PIN J17 IOSTANDARD LVCMOS33 } [get_ports {vgaGreen[0]}]
set_property -dict { PACKAGE_PIN H17 IOSTANDARD LVCMOS33 } [get_ports {vgaGreen[1]}]
set_property -dict { PACKAGE_PIN G17 IOSTANDARD LVCMOS33 } [get_ports {vgaGreen[2]}]
set_property -dict { PACKAGE_PIN D17 IOSTANDARD LVCMOS33 } [get_ports {vgaGreen[3]}]
set_property -dict { PACKAGE_PIN N18 IOSTANDARD LVCMOS33 } [get_ports {vgaBlue[0]}]
set_property -dict { PACKAGE_PIN L18 IOSTANDARD LVCMOS33 } [get_ports {vgaBlue[1]}]
set_property -dict { PACKAGE_PIN K18 IOSTANDARD LVCMOS33 } [get_ports {vgaBlue[2]}]
set_property -dict { PACKAGE_PIN J18 IOSTANDARD LVCMOS33 } [get_ports {vgaBlue[3]}]
set_property -dict { PACKAGE_PIN P19 IOSTANDARD LVCMOS33 } [get_ports Hsync]
set_property -dict { PACKAGE_PIN R19 IOSTANDARD LVCMOS33 } [get_ports Vsync]

## The button, the UART and the LEDs are asynchronous to every clock (each input has a two-flop
## synchroniser in soc_top / soc_uart; the LEDs are seen by eye); the VGA outputs leave from one
## clk_pix register each into a resistor ladder and a monitor that recovers its own pixel clock.
## None has an external timing relation worth constraining, so none is timed.
set_false_path -from [get_ports {btnC RsRx}]
set_false_path -to [get_ports {RsTx led[*] vgaRed[*] vgaGreen[*] vgaBlue[*] Hsync Vsync}]

## Configuration (from the master file)
set_property CONFIG_VOLTAGE 3.3 [current_design]
set_property CFGBVS VCCO [current_design]
