#!/bin/sh
# qemu_run.sh MACHINE IMAGE [STATUS [TEXT]] — runs a firmware image under
# qemu-system-arm with semihosting (its console output is printed) and
# checks the exit status the image reported (default 0) and, when given,
# that the output contains TEXT.  A run longer than QEMU_TIMEOUT seconds
# (default 120) is a failure.
set -u
machine=$1 image=$2 want=${3:-0} text=${4:-}
out=$(timeout "${QEMU_TIMEOUT:-120}" qemu-system-arm -M "$machine" -display none -monitor none -serial none \
    -semihosting-config enable=on,target=native -kernel "$image" 2>&1)
status=$?
[ -n "$out" ] && printf '%s\n' "$out"
if [ "$status" != "$want" ]; then
    echo "FAIL: $image on $machine: exit status $status, expected $want"
    exit 1
fi
if [ -n "$text" ] && ! printf '%s' "$out" | grep -qF "$text"; then
    echo "FAIL: $image on $machine: output lacks \"$text\""
    exit 1
fi
exit 0
