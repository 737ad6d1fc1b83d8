#!/usr/bin/env bash
# `make fresh-check`: the README's two commands on a fresh Debian 12, as a new user meets them. A
# minimal Debian 12 (debootstrap minbase with git, make and ca-certificates only) is made in
# $BUILD/fresh/root, the repository's committed HEAD is cloned into it (a local `git clone`: what
# is committed, not the working tree), and there, chrooted, `make run` (headless, FRAMES frames) and
# then `make test` install what they miss through tools/setup.sh and run. At the end a table: step,
# seconds, result; the exit status is 1 if either command failed.
#
# Here in mk/, with the build it checks: tools/setup.sh and its package lists are what a fresh
# machine depends on, and a list that misses a package fails here first. It is not a test suite
# (tests/run_all.sh runs those inside a built tree; this builds the tree from nothing).
#
# Needs root (debootstrap, chroot, mounts) and debootstrap, which it installs through tools/setup.sh
# (tools/packages-fresh.txt) when missing. What the host needs to reach the package registries is
# copied in at run time, no host named here: its Debian apt sources (the mirror is read from them),
# its apt settings of the Acquire group, /etc/pip.conf, the CA bundle and
# /usr/local/share/ca-certificates/, /etc/resolv.conf. /proc, /sys, /dev and /dev/pts are
# bind-mounted while the commands run; on exit, failure or Ctrl-C every process still running in
# the root is ended and everything is unmounted.
#
# Each run starts from a pristine root: the old one is deleted. debootstrap's result is kept as a
# tarball in $BUILD/fresh/cache/ (named after the mirror, suite and packages; delete it to bootstrap
# anew), taken before anything else touches the root, so a rerun unpacks it in seconds instead of
# bootstrapping again (~35 s).
#
# Quiet: one line per step with its seconds; each step's output in $BUILD/fresh/logs/STEP.log,
# whose tail is shown when the step fails. FRAMES (default 4): the frames of the headless run.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd -P)
build="${BUILD:-build}"
[[ "$build" == /* ]] || build="$repo/$build"
fresh="$build/fresh"
root="$fresh/root"
logs="$fresh/logs"
suite=bookworm
includes=git,make,ca-certificates
frames="${FRAMES:-4}"
project=/root/project  # where the clone lives inside the root

if [ "$(id -u)" -ne 0 ]; then
    echo "fresh-check: needs root (debootstrap, chroot and bind mounts); run it as root, e.g. sudo make fresh-check" >&2
    exit 2
fi
if ! command -v debootstrap >/dev/null; then
    bash "$repo/tools/setup.sh" packages-fresh.txt
fi

# The Debian mirror the host uses: the URIs of its deb822 stanza for the release itself, or the
# first `deb` line of sources.list.
host_mirror() {
    local sources=/etc/apt/sources.list.d/debian.sources
    if [ -f "$sources" ]; then
        awk -v suite="$suite" '
            /^[[:space:]]*$/ { if (uri != "" && match_suite) { print uri; found = 1; exit } uri = ""; match_suite = 0; next }
            tolower($1) == "uris:" { uri = $2 }
            tolower($1) == "suites:" { for (i = 2; i <= NF; i++) if ($i == suite) match_suite = 1 }
            END { if (!found && uri != "" && match_suite) print uri }' "$sources"
    elif [ -f /etc/apt/sources.list ]; then
        sed -n -E 's/^deb[[:space:]]+(\[[^]]*\][[:space:]]+)?([^[:space:]]+).*/\2/p' /etc/apt/sources.list | head -n 1
    fi
}
mirror=$(host_mirror)
if [ -z "$mirror" ]; then
    echo "fresh-check: no Debian mirror found in /etc/apt/sources.list.d/debian.sources or /etc/apt/sources.list" >&2
    exit 2
fi

# Leftovers of an interrupted run (a killed shell runs no trap): unmount before deleting anything.
unmount_leftovers() {
    local m
    for m in $(findmnt -rn -o TARGET | grep -E "^$root(/|$)" | sort -r); do
        umount "$m" 2>/dev/null || umount -l "$m"
    done
}

# ---- cleanup: end what still runs in the root, unmount, on every exit ----
mounted=()  # mount points in mount order; unmounted in reverse
processes_in_root() {
    local link pid
    for link in /proc/[0-9]*/root; do
        pid=${link#/proc/}
        pid=${pid%/root}
        [ "$(readlink "$link" 2>/dev/null)" = "$root" ] && echo "$pid"
    done
    return 0
}
cleanup() {
    local pids i
    pids=$(processes_in_root)
    if [ -n "$pids" ]; then
        kill -TERM $pids 2>/dev/null || true
        sleep 2
        pids=$(processes_in_root)
        [ -z "$pids" ] || kill -KILL $pids 2>/dev/null || true
    fi
    for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
        umount "${mounted[i]}" 2>/dev/null || umount -l "${mounted[i]}" ||
            echo "fresh-check: could not unmount ${mounted[i]}" >&2
    done
    mounted=()
    unmount_leftovers  # debootstrap's own /proc, when it was interrupted
}
trap cleanup EXIT
# The trap can run inside a step, whose output goes to its log: fd 3 is the caller's stderr.
exec 3>&2
trap 'printf "\nfresh-check: interrupted (processes in the root ended, mounts undone)\n" >&3; exit 130' INT
trap 'exit 143' TERM

# ---- steps: one line each, output in a log, the table at the end ----
table=()
failed=0
# step NAME COMMAND...: run COMMAND with its output in $logs/NAME.log; print "NAME ... N s";
# on failure the log's tail. Adds the step's row to the table; returns COMMAND's status.
step() {
    local name="$1" start=$SECONDS status=0 result
    shift
    printf 'fresh-check: %-12s' "$name"
    "$@" >"$logs/$name.log" 2>&1 || status=$?
    if [ "$status" -eq 0 ]; then result=ok; else result="FAILED (status $status)"; fi
    printf ' %5d s  %s  (log: %s)\n' $((SECONDS - start)) "$result" "${logs#"$repo"/}/$name.log"
    if [ "$status" -ne 0 ]; then
        tail -n 25 "$logs/$name.log" | sed 's/^/  | /' >&2
    fi
    table+=("$(printf '%-12s %7d  %s' "$name" $((SECONDS - start)) "$result")")
    return "$status"
}

unmount_leftovers
rm -rf --one-file-system "$root" "$logs"
mkdir -p "$root" "$logs" "$fresh/cache"
cache="$fresh/cache/$suite-minbase-$(printf '%s %s' "$mirror" "$includes" | sha256sum | cut -c1-12).tar"

bootstrap() {
    if [ -f "$cache" ]; then
        echo "unpacking $cache"
        tar -C "$root" --numeric-owner -xpf "$cache"
    else
        debootstrap --variant=minbase --include="$includes" "$suite" "$root" "$mirror" &&
            tar -C "$root" --numeric-owner --one-file-system -cf "$cache.part" . &&
            mv "$cache.part" "$cache"
    fi
}

# What the host needs to reach the package registries (nothing else of the host's configuration).
copy_host_access() {
    local f
    for f in /etc/apt/sources.list /etc/apt/sources.list.d/debian.sources /etc/pip.conf \
             /etc/resolv.conf /etc/ssl/certs/ca-certificates.crt; do
        [ -f "$f" ] && install -D -m 644 "$f" "$root$f"
    done
    # apt's own debootstrap list is replaced by the host's sources, when the host has deb822 ones.
    [ -f /etc/apt/sources.list.d/debian.sources ] && [ ! -f /etc/apt/sources.list ] &&
        rm -f "$root/etc/apt/sources.list"
    # Settings of the Acquire group (proxies, validity checks of a snapshot mirror's Release files).
    for f in /etc/apt/apt.conf.d/*; do
        [ -f "$f" ] && grep -q '^[[:space:]]*Acquire::' "$f" && install -m 644 "$f" "$root$f"
    done
    if [ -d /usr/local/share/ca-certificates ]; then
        mkdir -p "$root/usr/local/share/ca-certificates"
        cp -a /usr/local/share/ca-certificates/. "$root/usr/local/share/ca-certificates/"
    fi
    return 0
}

clone_head() {
    local head
    head=$(git -C "$repo" rev-parse HEAD)
    git clone --quiet --no-hardlinks "$repo" "$root$project" &&
        git -C "$root$project" checkout --quiet --detach "$head" &&
        echo "cloned $head ($(git -C "$repo" log -1 --format=%s "$head" | cut -c1-80))"
}

mount_binds() {
    local m
    for m in /proc /sys /dev /dev/pts; do
        mount --bind "$m" "$root$m"
        mounted+=("$root$m")
    done
}

# in_root COMMAND: run a shell command in the root's project, in a clean environment (a login's;
# no DISPLAY, CI=true: headless).
in_root() {
    chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb CI=true \
        PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        bash -c "cd $project && $1"
}

echo "fresh-check: Debian $suite from $mirror in ${root#"$repo"/}"
step bootstrap bootstrap || exit 1
step host-access copy_host_access || exit 1
step clone clone_head || exit 1
mount_binds
# CI=true is in the environment (in_root), as .ci/run has it, not on make's command line: there it
# would reach every sub-make, also the window suite's `make run`, which unsets CI to have a window.
step "make-run" in_root "make run FRAMES=$frames" || failed=1
step "make-test" in_root "make test" || failed=1
cleanup

summary=$(grep -E '^[0-9]+ passed, [0-9]+ failed' "$logs/make-test.log" | tail -n 1 || true)
failing=$(sed -n -E 's/^FAIL +([^ ]+).*/\1/p' "$logs/make-test.log" | tr '\n' ' ' || true)
echo
printf '%-12s %7s  %s\n' step seconds result
printf '%s\n' "${table[@]}"
[ -z "$summary" ] || echo "make test: $summary${failing:+ (failed: ${failing% })}"
exit "$failed"
