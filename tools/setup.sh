#!/usr/bin/env bash
# Install the Debian packages listed in tools/packages.txt (or the list files given as arguments,
# e.g. tools/packages-synth.txt) that are missing, then make the project's Python venv (.venv/ at
# the repository root, never the system Python) with the pinned tools/requirements.txt. Idempotent:
# when everything is present it only checks (well under a second) and changes nothing.
set -euo pipefail
cd "$(dirname "$0")"
lists=("$@")
[ ${#lists[@]} -gt 0 ] || lists=(packages.txt)

missing=()
for list in "${lists[@]}"; do
    while read -r pkg; do
        [[ -z "$pkg" || "$pkg" == \#* ]] && continue
        if ! dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed"; then
            missing+=("$pkg")
        fi
    done < "$(basename "$list")"
done

if [ ${#missing[@]} -gt 0 ]; then
    echo "setup: installing ${missing[*]}"
    sudo=""
    if [ "$(id -u)" -ne 0 ]; then
        sudo="sudo"
    fi
    export DEBIAN_FRONTEND=noninteractive
    $sudo apt-get update -qq
    $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

# The venv: (re)installed when the stamp (the hash of requirements.txt it was made from) differs,
# so a changed pin takes effect and a finished venv costs one sha256sum.
venv=../.venv
want=$(sha256sum requirements.txt | cut -d' ' -f1)
if [ "$(cat "$venv/.requirements.sha256" 2>/dev/null)" != "$want" ] || [ ! -x "$venv/bin/python" ]; then
    echo "setup: Python venv .venv/ from tools/requirements.txt"
    [ -x "$venv/bin/python" ] || python3 -m venv "$venv"
    "$venv/bin/python" -m pip install -q -r requirements.txt
    echo "$want" > "$venv/.requirements.sha256"
fi
