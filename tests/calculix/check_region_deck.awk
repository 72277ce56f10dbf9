# check_region_deck.awk — a region deck (organ_deck --sites) against the
# committed CalculiX data of its sites (region_dat.awk): each site's loads
# sum to 1 N and its site point is the data's (to 1e-9 mm), and the deck has
# as many sites as the data.
#
#   awk -f check_region_deck.awk DECK.inp DATA.csv
#
# Exits 1 with a line per site that differs.

FNR == 1 { file++ }
file == 1 && $1 == "**" && $2 == "SITE" { n++; pt[$3] = $6 " " $7 " " $8; next }
file == 1 && $1 == "**" && $2 == "PATCH" { w[$3] += $5; next }
file == 2 && FNR > 1 {
    split($0, f, ",")
    if (!(f[1] in want)) { m++ }
    want[f[1]] = 1
    split(pt[f[1]], a, " "); d = 0
    for (i = 1; i <= 3; i++) d += (a[i] - f[3 + i]) ^ 2
    if (!(f[1] in pt) || d > 1e-18) {
        printf "%s:%d: site %s at %s %s %s, the deck's at %s\n", FILENAME, FNR, f[1], f[4], f[5], f[6], pt[f[1]]
        bad = 1
    }
}

END {
    for (k = 1; k <= n; k++) {
        if (!(k in want) || w[k] < 1 - 1e-12 || w[k] > 1 + 1e-12) {
            printf "site %d: loads sum to %.15g N%s\n", k, w[k], k in want ? "" : ", not in the data"
            bad = 1
        }
    }
    if (n == 0 || n != m || bad) { printf "FAILED: %d sites in the deck, %d in the data\n", n, m; exit 1 }
    printf "ok: %d sites, each loaded with 1 N, at the data's site points\n", n
}
