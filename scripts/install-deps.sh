#!/bin/sh
# Install the Debian packages dynx needs, only those missing. Without root: print the exact
# apt-get line and exit 2.
#   sh scripts/install-deps.sh [--with-paraview]
# --with-paraview (CI, .ci/run): also headless ParaView (paraview python3-paraview xvfb
# xauth), so the pvpython regression cases (live_view_paraview, mpi_mixed_solids) run
# instead of being skipped. `make run` and `make test` do not ask for it: ParaView stays
# optional for users. Its cost on a fresh Debian 12 with dynx's packages (apt-get -s with an
# empty dpkg status, both package lists): 289 more packages, 273 MB to download, 1.43 GB
# installed (docs/history.md, "CI installs ParaView").
set -e
PKGS="gfortran make libopenmpi-dev openmpi-bin libhdf5-openmpi-dev hdf5-tools libmetis-dev libmumps-dev libarpack2-dev \
liblapack-dev libblas-dev libfftw3-dev gnuplot-nox python3 python3-numpy"
case "${1:-}" in
    --with-paraview) PKGS="$PKGS paraview python3-paraview xvfb xauth" ;;
    "") ;;
    *) echo "install-deps.sh: unknown option '$1' (known: --with-paraview)" >&2; exit 2 ;;
esac
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
line="apt-get install -y --no-install-recommends$missing"
if [ "$(id -u)" -ne 0 ]; then
    # without root: say exactly what to run, change nothing
    echo "dynx: missing Debian packages:$missing" >&2
    echo "dynx: as root, run:  apt-get update && $line" >&2
    echo "dynx: without root: ask the administrator to run that line; or build inside a" >&2
    echo "dynx:   container (podman or docker: 'podman run -it -v \$PWD:/dynx -w /dynx debian:12'," >&2
    echo "dynx:   then the line above and 'make run' as the container's root); or install the" >&2
    echo "dynx:   libraries in your home with Spack ('spack install openmpi hdf5+fortran+mpi" >&2
    echo "dynx:   metis mumps arpack-ng fftw', then 'spack load' them) and build with" >&2
    echo "dynx:   'make all' (the Makefile takes h5pfc from PATH); docs/manual/README.md, 1." >&2
    exit 2
fi
echo "dynx: installing missing Debian packages:$missing"
apt-get update -qq
DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing
