# ccx_cached.sh — sourced by run_reference.sh and run_organ.sh: run CalculiX
# on a deck unless its results are already there.
#
#   ccx_cached WORK RUN THREADS TIME_FORMAT MESSAGE
#
# WORK/RUN.inp.new is the deck just written.  When it equals WORK/RUN.inp
# and that run's .dat and .time are present, it is dropped and the results
# are reused; otherwise it becomes RUN.inp and CalculiX runs on it with
# THREADS threads, timed by /usr/bin/time -f TIME_FORMAT into RUN.time
# (written only when the run finished).  MESSAGE describes the run.
ccx_cached() {
    work=$1 run=$2 threads=$3 time_format=$4 message=$5
    if cmp -s "$work/$run.inp.new" "$work/$run.inp" && [ -s "$work/$run.dat" ] && [ -s "$work/$run.time" ]; then
        rm "$work/$run.inp.new"
        echo "calculix: $run: deck unchanged, reusing its results" >&2
        return 0
    fi
    mv "$work/$run.inp.new" "$work/$run.inp"
    rm -f "$work/$run.dat" "$work/$run.time"
    echo "calculix: $run: $message ..." >&2
    (cd "$work" && OMP_NUM_THREADS=$threads /usr/bin/time -f "$time_format" -o "$run.time.new" \
        ccx -i "$run" > "$run.log" 2>&1) || { echo "calculix: $run failed, see $work/$run.log" >&2; exit 1; }
    grep -q "Job finished" "$work/$run.log" || { echo "calculix: $run did not finish, see $work/$run.log" >&2; exit 1; }
    mv "$work/$run.time.new" "$work/$run.time"
}
