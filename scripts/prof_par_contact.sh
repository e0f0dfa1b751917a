#!/bin/sh
# CPU time of the contact stage by function, serial against each rank of an NP run, on the
# contact bench deck (scripts/bench_par_contact.sh: NCUBE cubes, NCYC cycles), from perf
# samples of the process's own CPU clock (perf record -e cpu-clock, F samples per second):
# unlike wall time this does not count the time a rank waits descheduled, so it can be
# compared on a loaded shared machine. Prints per run the CPU ms of the whole run, of the
# contact functions (dx_contact*, dx_par_contact*, bucket sort, pass_node) and of MPI and
# the kernel (waiting in collectives, yields), and the contact functions one by one.
#   NP=2 NCUBE=512 NCYC=200 sh scripts/prof_par_contact.sh
set -e
cd "$(dirname "$0")/.."
B=build/prof_par_contact
N=${NCUBE:-512}
NCYC=${NCYC:-200}
NP=${NP:-2}
F=${F:-2000}
mkdir -p $B
python3 scripts/gen_contact_decks.py cubes --ncube "$N" --ncyc "$NCYC" $B/cubes.k
opts="--oversubscribe --mca mpi_yield_when_idle 1"
[ "$(id -u)" = 0 ] && opts="$opts --allow-run-as-root"
rm -rf $B/s $B/p $B/perf.*
perf record -q -e cpu-clock -F "$F" -o $B/perf.s.data bin/dynx -i $B/cubes.k -o $B/s > $B/s.log 2>&1
mpirun $opts -np "$NP" sh -c "perf record -q -e cpu-clock -F $F -o $B/perf.\$OMPI_COMM_WORLD_RANK.data bin/dynx -i $B/cubes.k -o $B/p" > $B/p.log 2>&1
echo "commit $(git rev-parse --short HEAD 2>/dev/null), load $(cut -d' ' -f1 /proc/loadavg), $N cubes, $NCYC cycles, NP $NP, $F samples/s"
r=0
for f in s $(seq 0 $((NP - 1))); do
    perf report -i $B/perf.$f.data -n --stdio --sort sym 2>/dev/null > $B/report.$f.txt
    python3 - $B/report.$f.txt "$f" "$F" "$NCYC" <<'PY'
import re, sys
path, run, hz, ncyc = sys.argv[1], sys.argv[2], float(sys.argv[3]), int(sys.argv[4])
tot, cat, fun = 0, {'contact': 0, 'MPI + kernel': 0, 'other': 0}, {}
for line in open(path):
    m = re.match(r'\s*[0-9.]+%\s+(\d+)\s+\[(.)\]\s+(\S+)', line)
    if not m:
        continue
    n, kind, s = int(m.group(1)), m.group(2), m.group(3)
    tot += n
    if re.search(r'contact|bucket_sort|segment_box|pass_node|project_point', s):
        c = 'contact'
        fun[s] = fun.get(s, 0) + n
    elif kind == 'k' or re.search(r'sched|mca_|ompi|opal|pmix|MPI', s):
        c = 'MPI + kernel'
    else:
        c = 'other'
    cat[c] += n
ms = lambda n: 1000.0*n/hz
print('%s: whole run %.0f ms CPU; contact %.0f ms (%.0f us per cycle); MPI + kernel %.0f ms; other %.0f ms'
      % ('serial' if run == 's' else 'rank ' + run, ms(tot), ms(cat['contact']),
         1000.0*ms(cat['contact'])/ncyc, ms(cat['MPI + kernel']), ms(cat['other'])))
print('   ' + '; '.join('%s %.0f' % (re.sub(r'^__|_MOD_', ' ', k).strip(), ms(v))
                       for k, v in sorted(fun.items(), key=lambda x: -x[1])[:12]))
PY
done
