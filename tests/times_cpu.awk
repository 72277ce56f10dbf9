# times_cpu.awk — the CPU seconds (user + system) of a shell's children,
# from the output of its `times` builtin (second line: "XmY.Ys XmY.Ys").
NR == 2 {
    split($1, u, "m")
    split($2, k, "m")
    printf "%d", u[1] * 60 + u[2] + k[1] * 60 + k[2]
}
