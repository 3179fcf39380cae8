#!/usr/bin/env bash
# The package as a new node meets it (not in CI: it needs root, debootstrap and a Debian mirror
# on the network). Builds the .deb (deploy/package.sh), installs it with apt into a clean
# Debian 12 chroot made by debootstrap (its dependencies come from the mirror, so a missing
# runtime dependency shows), and checks there, with no source or build tree in sight:
#   - the skyig user exists (sysusers), the unit is enabled, /etc/skyig/skyig.toml is a conffile;
#   - `skyig --version --caps` reads /usr/share/skyig;
#   - `skyig render --png /tmp/x.png` renders the default (physical) sky, precomputing its tables.
# The debootstrapped base is kept in build-package/bookworm-base.tar and reused; each run
# installs into a fresh copy. MIRROR overrides the Debian mirror.
#   sudo apt-get install debootstrap && sudo bash deploy/test-package.sh
set -euo pipefail
cd "$(dirname "$0")/.."
mirror=${MIRROR:-http://deb.debian.org/debian}
[ "$(id -u)" -eq 0 ] || { echo "test-package: run as root (debootstrap, chroot, mount)" >&2; exit 1; }
command -v debootstrap >/dev/null || { echo "test-package: needs debootstrap (apt-get install debootstrap)" >&2; exit 1; }

deb=$(bash deploy/package.sh | tail -n 1)
base=build-package/bookworm-base.tar
if [ ! -f "$base" ]; then
  staging=$(mktemp -d build-package/bookworm-debootstrap.XXXXXX)
  echo "test-package: debootstrap bookworm from $mirror (once)"
  debootstrap bookworm "$staging" "$mirror"
  tar -C "$staging" -cf "$base.part" . && mv "$base.part" "$base"
  rm -rf "$staging"
fi

root=$(mktemp -d build-package/bookworm-root.XXXXXX)
root=$(cd "$root" && pwd)
cleanup() {
  for m in dev/pts dev proc; do mountpoint -q "$root/$m" && umount "$root/$m"; done
  # Never delete through a mount left in place: that would be the machine's /dev.
  if grep -q " $root/" /proc/mounts; then
    echo "test-package: still mounted under $root; not removing it" >&2
  else
    rm -rf "$root"
  fi
}
trap cleanup EXIT
tar -C "$root" -xf "$base"
mount -t proc proc "$root/proc"          # skyig finds its data through /proc/self/exe
mount --bind /dev "$root/dev"
mount --bind /dev/pts "$root/dev/pts"
cp /etc/resolv.conf "$root/etc/resolv.conf"
cp "$deb" "$root/tmp/skyig.deb"
in_root() { chroot "$root" /usr/bin/env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root DEBIAN_FRONTEND=noninteractive "$@"; }

in_root apt-get update -q
in_root apt-get install -y -q --no-install-recommends /tmp/skyig.deb
[ ! -e "$root$(pwd)" ] || { echo "test-package: the source tree is visible in the chroot" >&2; exit 1; }

in_root getent passwd skyig
in_root test -L /etc/systemd/system/multi-user.target.wants/skyig.service
in_root dpkg-query -W -f='${Conffiles}\n' skyig | grep '/etc/skyig/skyig.toml' >/dev/null
caps=$(in_root skyig --version --caps)
echo "$caps"
grep -q 'Data files:    /usr/share/skyig (beside the executable)' <<<"$caps"
time in_root skyig render --png /tmp/x.png
in_root test -s /tmp/x.png
echo "test-package: $deb installs in a clean Debian 12 chroot and renders /tmp/x.png there"
