#!/usr/bin/env bash
# A scene cannot tell which keyboard was used: keys typed on the USB keyboard (socsim's model on
# soc_top's USB host, the firmware built with FW_USB_KEYBOARD) give the same frames, byte for byte,
# as the same keys typed on the UART at the same frames.
#
# Two scenes in one program (tetra and cubes, mk/builds.toml's tetra-cubes-usb), each with KEYS:
# the camera moved in each of its modes (m: fly, orbit, object and back), looks, arrows and the
# wireframe; key 2 between them switches to cubes. Run 1 types them on the USB keyboard; socsim
# prints each event the firmware takes from USB KEY with the doorbells before it. Run 2, on the same
# simulator with the keyboard plugged in but idle, sends each key's terminal bytes (this file's own
# table, not the firmware's) on the UART at that doorbell (--keys-at), so that the firmware reads
# them in the same frame. Every frame of both runs equals the golden model's (socsim's check) and
# the two runs' frames are identical. One program for both scenes: the keyboard's enumeration (about
# 9 of a run's frames) once, not once a scene.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
socsim="$1"
need_file "$socsim"
work=$(fresh_dir soc-usb-keys)

# The keys: what the USB model types ({NAME} for a key without a character), and the bytes a
# terminal sends for each (VT100 cursor keys).
scene_keys=(w i m s "{UP}" m "{DOWN}" j m f)
keys=("${scene_keys[@]}" 2 "${scene_keys[@]}")  # tetra's, key 2 (cubes), cubes'
declare -A term=(["{UP}"]=$'\e[A' ["{DOWN}"]=$'\e[B' ["{RIGHT}"]=$'\e[C' ["{LEFT}"]=$'\e[D')
text=$(printf '%s' "${keys[@]}")
elf="$soc_test_dir/tetra-cubes-usb.elf"
need_file "$elf.hex"

run_to "$work/usb.out" 300 "$socsim" --fw "$elf" --frames "$work/usb" --uart-log "$work/usb.uart" \
    --usb-keys-at "1:$text" --summary "$work/usb.summary"
expect_status 0 "socsim with the USB keyboard ($(tail -n 3 "$work/usb.out"))"
[ "$(summary usb_violations "$work/usb.summary")" = 0 ] || fail "the keyboard model saw violations"
[ "$(summary usb_reports_queued "$work/usb.summary")" = 0 ] ||
    fail "keys left untyped when the program ended: raise its FW_FRAMES (mk/builds.toml)"
# The presses the firmware took, in order, with their doorbells; the keys of one doorbell go as one
# --keys-at.
mapfile -t doorbells < <(sed -n 's/^socsim: usb key 0x\([0-9a-f]*\) press after doorbell \([0-9]*\) .*/\1 \2/p' \
    "$work/usb.out" | awk '$1 !~ /^e[0-7]$/ { print $2 }')
[ "${#doorbells[@]}" -eq "${#keys[@]}" ] ||
    fail "the firmware took ${#doorbells[@]} key presses from the USB keyboard, expected ${#keys[@]}"
keys_at=() group="" group_doorbell=""
for i in "${!keys[@]}"; do
    k=${keys[$i]}
    if [ "${doorbells[$i]}" != "$group_doorbell" ] && [ -n "$group" ]; then
        keys_at+=(--keys-at "$group_doorbell:$group")
        group=""
    fi
    group_doorbell=${doorbells[$i]}
    group+=${term[$k]:-$k}
done
keys_at+=(--keys-at "$group_doorbell:$group")

run_to "$work/uart.out" 300 "$socsim" --fw "$elf" --frames "$work/uart" --uart-log "$work/uart.uart" \
    "${keys_at[@]}" --summary "$work/uart.summary"
expect_status 0 "socsim with the same keys on the UART ($(tail -n 3 "$work/uart.out"))"
[ "$(summary keys_late "$work/uart.summary")" = 0 ] || fail "UART keys reached a later frame than their doorbell's"
[ "$(summary usb_keys_read "$work/uart.summary")" = 0 ] || fail "the idle USB keyboard gave keys"
same_pngs "$work/usb" "$work/uart" "the USB keyboard's frames against the UART's"
# The keys did something, in both runs alike (a scene that animates changes every frame, so the
# frames alone cannot tell): the firmware's answers to M (three modes in each scene), to F (the
# wireframe on in tetra, off in cubes) and to 2 (cubes), the same lines (a frame prints its notes in
# its own order: counted here, compared line for line below).
reactions() { grep -E '^(camera: |wireframe |scene [a-z]+:)' "$1" | sed 's/:.*//' || true; }
got=$(reactions "$work/usb.uart" | sort | uniq -c | awk '{ $1 = $1 "x"; print }' | tr '\n' ';')
want="6x camera;1x scene cubes;1x scene tetra;1x wireframe off;1x wireframe on;"
[ "$got" = "$want" ] || fail "the firmware's answers to the USB keyboard's M, F and 2: '$got', expected '$want'"
[ "$(reactions "$work/usb.uart")" = "$(reactions "$work/uart.uart")" ] ||
    fail "the firmware answered the keys differently on the USB keyboard and the UART"
pass "soc-usb-keys: ${#keys[@]} keys typed on the USB keyboard (tetra's 10, 2 for cubes, cubes' 10) give the same $(summary frames "$work/usb.summary") frames, byte for byte, as on the UART ($((${#keys_at[@]} / 2)) doorbells with keys); $(summary cycles "$work/usb.summary") cycles a run; the keyboard $(summary usb_keyboard "$work/usb.summary")"
