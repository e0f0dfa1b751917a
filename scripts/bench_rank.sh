#!/bin/sh
# One process of a benchmark run (scripts/bench_scaling.py), started directly or by mpirun:
#   sh scripts/bench_rank.sh PREFIX LIMIT_KB MODE cmd [args...]
# LIMIT_KB > 0: `ulimit -v LIMIT_KB` first (the per-rank memory limit of the "does not fit
# on one rank" test). MODE time: cmd runs under /usr/bin/time, which writes
# "maxrss_KiB user_s sys_s wall_s exit" to PREFIX.RANK (maxrss: the peak resident set,
# VmHWM at exit). MODE vmpeak: cmd runs in the background and its VmPeak (peak virtual
# size, what `ulimit -v` limits) is polled every 0.05 s from /proc; the last value read
# goes to PREFIX.RANK as "vmpeak_KiB". RANK: OMPI_COMM_WORLD_RANK, or 0.
prefix=$1
limit=$2
mode=$3
shift 3
r=${OMPI_COMM_WORLD_RANK:-0}
if [ "$limit" -gt 0 ]; then
    ulimit -v "$limit" || exit 2
fi
if [ "$mode" = time ]; then
    /usr/bin/time -f '%M %U %S %e %x' -o "$prefix.$r" "$@"
    exit $?
fi
"$@" &
pid=$!
peak=0
while kill -0 $pid 2>/dev/null; do
    v=$(sed -n 's/^VmPeak:[^0-9]*\([0-9]*\).*/\1/p' /proc/$pid/status 2>/dev/null)
    [ -n "$v" ] && [ "$v" -gt "$peak" ] && peak=$v
    sleep 0.05
done
wait $pid
rc=$?
echo "$peak" > "$prefix.$r"
exit $rc
