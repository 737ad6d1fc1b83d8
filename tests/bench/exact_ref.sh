#!/usr/bin/env bash
# The exact reference of `make bench-error`'s camera paths (bench/exact_ref):
#  1. its self-test on known polygons: a square whose edges pass through pixel centres covers
#     exactly 10 x 10 of them, each once (top-left rule, shared diagonal), either winding; a
#     triangle crossing the near plane is cut there; depth order holds in either drawing order;
#     nothing beyond the far plane;
#  2. against the firmware: tetra's camera path (52 views, the float backend with the depth
#     buffer, host build through the golden model) and the exact reference's render of the same
#     views' scene dumps agree to within 1 % of the framebuffer on every view - the two read the
#     same scene, camera and palette the same way (a convention mismatch shows as a large error).
source "$(dirname "$0")/../lib.sh"
need BUILD
work=$(fresh_dir exact-ref)

# 1.
"$BUILD/tools/exact_ref" --self-test || fail "exact_ref self-test"

# 2.
"$BUILD/fw-path/host-tetra-float-z" --zbuf --frames "$work/fw" --dump-scene "$work/scene" >"$work/host.log" \
    || fail "tetra path host run (see $work/host.log)"
mkdir -p "$work/exact"
"$BUILD/tools/exact_ref" --dir "$work/scene" "$work/exact" >/dev/null || fail "exact_ref --dir"
views=0
worst=0
for f in "$work"/exact/*.png; do
    d=$("$BUILD/tools/png_diff" --block 2 "$f" "$work/fw/$(basename "$f")" | awk '{print $4}')
    [ -n "$d" ] || fail "png_diff on $(basename "$f")"
    [ "$d" -gt "$worst" ] && worst=$d
    views=$((views + 1))
done
expect_eq "$views" 52 "views rendered"
[ "$worst" -le 768 ] || fail "a view differs from the exact reference in $worst pixels (> 1 %)"
pass "exact reference: self-test, tetra's 52 path views within $worst pixels of the firmware's"
