#!/bin/sh
# Install the Debian packages dynx needs, only those missing. Uses sudo when not root.
set -e
PKGS="gfortran make libopenmpi-dev openmpi-bin libhdf5-openmpi-dev hdf5-tools libmetis-dev \
liblapack-dev libblas-dev libfftw3-dev gnuplot-nox python3 python3-numpy"
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
[ -z "$missing" ] && exit 0
echo "dynx: installing missing Debian packages:$missing"
SUDO=""
[ "$(id -u)" -ne 0 ] && SUDO="sudo"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends $missing
