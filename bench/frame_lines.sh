# bench/frame_lines.sh — sourced by the benchmark scripts that read the firmware's UART log:
#   mean "WORDS" LOG   the mean of the number after WORDS (e.g. "gpu cycles") on its "frame N:" lines
#   commas N           N with thousands separators, as the docs' tables print numbers
mean() {
    awk -v f="$1" '/^frame / { k = split(f, w, " ")
                               for (i = 1; i + k <= NF; i++) {
                                   hit = 1
                                   for (j = 1; j <= k; j++) if ($(i + j - 1) != w[j]) hit = 0
                                   if (hit) { s += $(i + k); n++ }
                               } }
                   END { printf "%.0f", n ? s / n : 0 }' "$2"
}
commas() { echo "$1" | sed -E ':a; s/([0-9])([0-9]{3})($|[^0-9])/\1,\2\3/; ta'; }
