#!/bin/sh
# total_target.sh HEADER FRACTION — a shipped header's stated total errors
# (fit + discretisation, TFIT_<NAME>_FORWARD_TOTAL_MAX_MM and
# _CONTACT_TOTAL_MAX_N) within FRACTION of its peak displacement (the banner's
# "largest displacement of the training cases") and of its envelope's
# radius.  A copy with the forward total raised past the target must be
# refused (the check can fail).
set -eu
h=$1 frac=$2
verdict() {
    awk -v frac="$frac" '
        /largest displacement of the training cases:/ { for (i = 1; i <= NF; i++) if ($i == "mm") peak = $(i - 1) }
        /_FORWARD_TOTAL_MAX_MM / { fwd = $3 }
        /_CONTACT_TOTAL_MAX_N / { con = $3 }
        /_FORWARD_ENVELOPE_RADIUS / { rad = $3 }
        END {
            if (peak == "" || fwd == "" || con == "" || rad == "") { print "no totals, peak or radius in the header"; exit 2 }
            printf "forward total %g mm = %.2f %% of the peak %g mm; contact total %g N = %.2f %% of %g N (target %g %%)\n",
                   fwd, 100 * fwd / peak, peak, con, 100 * con / rad, rad, 100 * frac
            exit !(fwd <= frac * peak && con <= frac * rad)
        }' "$1"
}
out=$(verdict "$h") || { echo "$h: $out: beyond the target"; exit 1; }
tmp=$(mktemp)
trap 'rm -f "$tmp"' EXIT
awk -v frac="$frac" '/largest displacement of the training cases:/ { for (i = 1; i <= NF; i++) if ($i == "mm") peak = $(i - 1) }
    /_FORWARD_TOTAL_MAX_MM / { $3 = 1.01 * frac * peak } { print }' "$h" > "$tmp"
if verdict "$tmp" > /dev/null; then
    echo "total_target.sh accepted a copy of $h whose forward total is 1 % past the target"; exit 1
fi
echo "ok: $(basename "$h"): $out; a copy 1 % past it is refused"
