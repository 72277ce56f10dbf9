# support_reaction.awk — functions for dat_reactions.awk and dat_curve.awk
# (awk -f support_reaction.awk -f THE_OTHER.awk): the total reaction on the
# supports of a box deck, per printed block, from the .dat's
# "total force (fx,fy,fz) for set S" blocks (S = CLAMP, and SYMX / SYMY when
# the deck cuts the box at a mirror plane).
#
# RF is each node's external force.  The clamp carries all of it along the
# cut planes; normal to a cut, the cut's own nodes carry a reaction too (no
# load acts normal to a cut).  The mesh carries the share s of the force
# ("** SHARE s" in the deck); dividing by s gives the whole box's reaction.

# Reads the deck's SHARE line (call on deck lines).
function support_deck_line() {
    if ($1 == "**" && $2 == "SHARE") support_share = $3
}

# Call on each .dat line; returns 1 when the line was part of a total.
function support_dat_line(    set) {
    if ($0 ~ /total force \(fx,fy,fz\) for set (CLAMP|SYMX|SYMY)/) {
        set = $6
        support_set = set
        support_idx = ++support_count[set]
        support_time[set, support_idx] = $0 ~ /time/ ? $NF : ""
        return 1
    }
    if (support_set != "" && NF == 3) {
        support_r[support_set, support_idx, 1] = $1
        support_r[support_set, support_idx, 2] = $2
        support_r[support_set, support_idx, 3] = $3
        support_set = ""
        return 1
    }
    return 0
}

# Number of complete totals (every printed set has block k).
function support_blocks(    k, n) {
    n = support_count["CLAMP"]
    if ("SYMX" in support_count && support_count["SYMX"] != n) return -1
    if ("SYMY" in support_count && support_count["SYMY"] != n) return -1
    return n
}

# The whole box's reaction of block k as "rx,ry,rz".
function support_total(k,    s, r1, r2, r3) {
    s = support_share == "" ? 1 : support_share
    r1 = support_r["CLAMP", k, 1] + support_r["SYMX", k, 1]
    r2 = support_r["CLAMP", k, 2] + support_r["SYMY", k, 2]
    r3 = support_r["CLAMP", k, 3]
    return sprintf("%.10g,%.10g,%.10g", r1 / s, r2 / s, r3 / s)
}
