#!/usr/bin/env bash
# A scene cannot tell which keyboard was used: keys typed on the USB keyboard (socsim's model on
# soc_top's USB host, the firmware built with FW_USB_KEYBOARD) give the same frames, byte for byte,
# as the same keys typed on the UART at the same frames.
#
# Two scenes (tetra and cubes, their FW_FRAMES builds), each with KEYS: the camera moved in each of
# its modes (m: fly, orbit, object and back), looks, arrows and the wireframe. Run 1 types them on
# the USB keyboard; socsim prints each event the firmware takes from USB KEY with the doorbells
# before it. Run 2, on the same simulator with the keyboard plugged in but idle, sends each key's
# terminal bytes (this file's own table, not the firmware's) on the UART at that doorbell
# (--keys-at), so that the firmware reads them in the same frame. Every frame of both runs equals
# the golden model's (socsim's check) and the two runs' frames are identical.
source "$(dirname "$0")/../lib.sh"
source "$(dirname "$0")/soc_lib.sh"
need BUILD
socsim="$1"
need_file "$socsim"
work=$(fresh_dir soc-usb-keys)

# The keys: what the USB model types ({NAME} for a key without a character), and the bytes a
# terminal sends for each (VT100 cursor keys).
keys=(w i m s "{UP}" m "{DOWN}" j m f)
declare -A term=(["{UP}"]=$'\e[A' ["{DOWN}"]=$'\e[B' ["{RIGHT}"]=$'\e[C' ["{LEFT}"]=$'\e[D')
text=$(printf '%s' "${keys[@]}")

one_scene() {
    local s="$1" elf="$soc_test_dir/$1-usb.elf" out="$work/$1" doorbells keys_at=() group="" group_doorbell="" i k
    need_file "$elf.hex"
    mkdir -p "$out"
    run_to "$out/usb.out" 300 "$socsim" --fw "$elf" --frames "$out/usb" --uart-log "$out/usb.uart" \
        --usb-keys-at "1:$text" --summary "$out/usb.summary"
    expect_status 0 "$s: socsim with the USB keyboard ($(tail -n 3 "$out/usb.out"))"
    [ "$(summary usb_violations "$out/usb.summary")" = 0 ] || fail "$s: the keyboard model saw violations"
    [ "$(summary usb_reports_queued "$out/usb.summary")" = 0 ] ||
        fail "$s: keys left untyped when the program ended: raise its FW_FRAMES"
    # The presses the firmware took, in order, with their doorbells; the keys of one doorbell go as
    # one --keys-at.
    mapfile -t doorbells < <(sed -n 's/^socsim: usb key 0x\([0-9a-f]*\) press after doorbell \([0-9]*\) .*/\1 \2/p' \
        "$out/usb.out" | awk '$1 !~ /^e[0-7]$/ { print $2 }')
    [ "${#doorbells[@]}" -eq "${#keys[@]}" ] ||
        fail "$s: the firmware took ${#doorbells[@]} key presses from the USB keyboard, expected ${#keys[@]}"
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

    run_to "$out/uart.out" 300 "$socsim" --fw "$elf" --frames "$out/uart" --uart-log "$out/uart.uart" \
        "${keys_at[@]}" --summary "$out/uart.summary"
    expect_status 0 "$s: socsim with the same keys on the UART ($(tail -n 3 "$out/uart.out"))"
    [ "$(summary keys_late "$out/uart.summary")" = 0 ] || fail "$s: UART keys reached a later frame than their doorbell's"
    [ "$(summary usb_keys_read "$out/uart.summary")" = 0 ] || fail "$s: the idle USB keyboard gave keys"
    same_pngs "$out/usb" "$out/uart" "$s: the USB keyboard's frames against the UART's"
    # The keys did something, in both runs alike (a scene that animates changes every frame, so the
    # frames alone cannot tell): the firmware's answers to M (three modes) and F, the same lines.
    reactions() { grep -E '^(camera: |wireframe )' "$1" || true; }
    [ "$(reactions "$out/usb.uart" | grep -c '^camera: ')" -eq 3 ] && reactions "$out/usb.uart" | grep -q '^wireframe on' ||
        fail "$s: the firmware did not answer the USB keyboard's M and F ($(reactions "$out/usb.uart" | tr '\n' ';'))"
    [ "$(reactions "$out/usb.uart")" = "$(reactions "$out/uart.uart")" ] ||
        fail "$s: the firmware answered the keys differently on the USB keyboard and the UART"
    echo "$s: $(summary frames "$out/usb.summary") frames ($((${#keys_at[@]} / 2)) with keys) the same on the USB keyboard and the UART; $(reactions "$out/usb.uart" | tr '\n' ';' | sed 's/;$//'); $(summary cycles "$out/usb.summary") cycles; the keyboard $(summary usb_keyboard "$out/usb.summary")"
}

each_scene 2 one_scene tetra cubes
pass "soc-usb-keys: ${#keys[@]} keys typed on the USB keyboard in tetra and cubes give the same frames, byte for byte, as on the UART"
