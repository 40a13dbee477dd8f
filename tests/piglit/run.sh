#!/usr/bin/env bash
# Runs piglit tests (lines "name|command" as `piglit print-cmd --format '{name}|{command}'`
# prints them) on the GL found through LD_LIBRARY_PATH (unset: the system's, Mesa) under the
# X display $DISPLAY, and prints "name<TAB>verdict" per test. The verdict is piglit's own
# (pass, fail, skip, warn) or crash / timeout when the test printed none.
# Usage: tests/piglit/run.sh LIST [TIMEOUT_SECONDS]
set -u
list=$1
limit=${2:-60}
bin=$(dirname "$(command -v piglit)")/../lib/x86_64-linux-gnu/piglit/bin
export PIGLIT_PLATFORM=glx
while IFS='|' read -r name cmd; do
    [ -z "$name" ] && continue
    # shellcheck disable=SC2086
    set -- $cmd
    exe="$bin/$(basename "$1")"
    shift
    for _try in 1 2 3; do
        out=$(timeout -k 5 "$limit" "$exe" "$@" 2>&1 </dev/null)
        rc=$?
        # A busy Xvfb now and then refuses a connection: try again.
        case "$out" in *"XOpenDisplay failed"*) sleep 1 ;; *) break ;; esac
    done
    verdict=$(printf '%s\n' "$out" | sed -n 's/^PIGLIT: {"result": "\([a-z]*\)" }.*/\1/p' | tail -1)
    if [ -z "$verdict" ]; then
        if [ $rc -eq 124 ] || [ $rc -eq 137 ]; then verdict=timeout; else verdict=crash; fi
    fi
    printf '%s\t%s\n' "$name" "$verdict"
done < "$list"
