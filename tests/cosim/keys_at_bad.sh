#!/usr/bin/env bash
# --keys-at's malformed specs are refused with a clear message and the usage status (2), nothing
# run, by each program that takes it: the host build (bsp/host), gpusim cosim and socsim (its
# --usb-keys-at too, cosim/keys_at.h's parser), and a socsim keyboard option without the keyboard
# (--usb-unplugged) likewise. N counts doorbells from 1, fF frames from 0 (a run's frame 0 is its
# first: f0 is legal, 0 is not).
#   usage: keys_at_bad.sh SOCSIM_USB
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/../soc/soc_lib.sh"
need GPUSIM FW_ELF BUILD
socsim_usb=${1:?usage: keys_at_bad.sh SOCSIM_USB}
host="$BUILD/fw-test/host-tetra"
soc_elf="$soc_test_dir/tetra-3f.elf"
need_file "$GPUSIM" "$FW_ELF" "$host" "$socsim_usb" "$soc_elf.hex"
work=$(fresh_dir cosim-keys-at-bad)

# refused WHAT MESSAGE COMMAND...: status 2 within 10 s, MESSAGE on its output, no frame written.
refused() {
    local what="$1" message="$2"
    shift 2
    rm -rf "$work/frames"
    run_to "$work/out" 10 "$@"
    [ "$status" -eq 2 ] || fail "$what: status $status, expected 2 (a usage error): $(head -n 3 "$work/out")"
    grep -qF -- "$message" "$work/out" || fail "$what: no '$message' in: $(head -n 3 "$work/out")"
    [ ! -e "$work/frames" ] || [ -z "$(ls "$work/frames")" ] || fail "$what: frames written"
}
n=0
for spec in 'x:z' 'f:z' '0:z' 'fz' '5' 'f-1:z' '1x:z' ':z'; do
    refused "host build --keys-at '$spec'" "--keys-at wants N:TEXT" "$host" --frames "$work/frames" --keys-at "$spec"
    refused "gpusim cosim --keys-at '$spec'" "--keys-at wants N:TEXT" "$GPUSIM" cosim --fw "$FW_ELF" --frames "$work/frames" --keys-at "$spec"
    refused "socsim --keys-at '$spec'" "--keys-at wants N:TEXT" "$socsim_usb" --fw "$soc_elf" --frames "$work/frames" --keys-at "$spec"
    refused "socsim --usb-keys-at '$spec'" "--keys-at wants N:TEXT" "$socsim_usb" --fw "$soc_elf" --frames "$work/frames" --usb-keys-at "$spec"
    n=$((n + 4))
done
refused "socsim --usb-unplugged --usb-keys-at" "which --usb-unplugged leaves out" \
    "$socsim_usb" --fw "$soc_elf" --frames "$work/frames" --usb-unplugged --usb-keys-at 1:a
refused "socsim --usb-unplugged --usb-window" "which --usb-unplugged leaves out" \
    "$socsim_usb" --fw "$soc_elf" --frames "$work/frames" --usb-unplugged --usb-window
refused "socsim --usb-keys-at with a key it cannot type" "--usb-keys-at" \
    "$socsim_usb" --fw "$soc_elf" --frames "$work/frames" --usb-keys-at '1:{NOKEY}'
pass "keys-at-bad: $((n + 3)) malformed key options refused with status 2 and a message (host build, gpusim cosim, socsim)"
