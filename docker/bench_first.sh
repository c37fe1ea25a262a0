#!/usr/bin/env bash
# `./vrrw bench first [--mirror URL] [--keep]` (./vrrw checks the options, then runs this with MIRROR and KEEP,
# 1 or empty): the README's first command on a bare Debian 12, timed. Without a Docker engine: a minimal Debian 12
# (debootstrap --variant=minbase bookworm) in a folder under /var/tmp, given git and ca-certificates to clone this
# repository's committed HEAD and nothing else, then `./vrrw demo` run in it (chroot) from the first line to the
# report. Prints each line with its second, then a JSON line: the packages, the configure and build, the
# evaluation, the total. Needs root and debootstrap; Ctrl-C unmounts and removes it all (KEEP leaves the folder for
# a look). The host's name and resolver are copied in, as an installed system has them, and the host's own CA
# certificates (a proxy's), so apt and pip reach their servers as the host does.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
mirror=$1 keep=${2:-}
load() { cut -d ' ' -f 1-3 /proc/loadavg; }
[ "$(id -u)" -eq 0 ] || { echo "vrrw: bench first: needs root (debootstrap, mount, chroot)" >&2; exit 2; }
command -v debootstrap >/dev/null || { echo "vrrw: bench first: needs debootstrap (apt-get install debootstrap)" >&2; exit 2; }
git -C "$root" rev-parse --verify -q HEAD >/dev/null || { echo "vrrw: bench first: $root: no commit to clone" >&2; exit 2; }

dir=$(mktemp -d /var/tmp/vrrw_bench_first.XXXXXX)
sys=$dir/debian
cleanup() {
  for m in "$sys/dev" "$sys/sys" "$sys/proc"; do mountpoint -q "$m" && umount -R "$m" 2>/dev/null || umount -lR "$m" 2>/dev/null || true; done
  if [ -z "$keep" ]; then rm -rf --one-file-system -- "$dir"; else echo "bench first: kept $dir" >&2; fi
}
trap cleanup EXIT
trap 'exit 130' INT TERM

echo "bench first: a bare Debian 12 in $sys ($mirror), load $(load)" >&2
debootstrap --variant=minbase bookworm "$sys" "$mirror" >"$dir/debootstrap.log" 2>&1 \
  || { tail -n 5 "$dir/debootstrap.log" >&2; echo "vrrw: bench first: debootstrap failed (log above)" >&2; exit 1; }
printf 'deb %s bookworm main\ndeb %s bookworm-updates main\ndeb %s-security bookworm-security main\n' \
  "$mirror" "$mirror" "$mirror" >"$sys/etc/apt/sources.list"
cp /etc/resolv.conf /etc/hosts "$sys/etc/"
mount -t proc proc "$sys/proc" && mount --rbind /sys "$sys/sys" && mount --rbind /dev "$sys/dev"
chroot "$sys" /bin/sh -c 'apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends git ca-certificates' \
  >"$dir/prerequisites.log" 2>&1 || { tail -n 5 "$dir/prerequisites.log" >&2; echo "vrrw: bench first: git could not be installed" >&2; exit 1; }
if compgen -G "/usr/local/share/ca-certificates/*.crt" >/dev/null; then
  cp /usr/local/share/ca-certificates/*.crt "$sys/usr/local/share/ca-certificates/"
  chroot "$sys" update-ca-certificates >/dev/null 2>&1
fi
git clone -q "$root" "$sys/root/vrrw"
commit=$(git -C "$sys/root/vrrw" log -1 --format=%h)
echo "bench first: $commit cloned; ./vrrw demo starts" >&2

# The command, each line with the seconds since its start; the parts from the lines that end them.
log=$dir/first.log
micros() { echo "${EPOCHREALTIME/./}"; }
seconds() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", (b - a) / 1e6 }'; }
start=$(micros)
set +e
chroot "$sys" /usr/bin/env -i HOME=/root LANG=C.UTF-8 PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  PIP_CERT=/etc/ssl/certs/ca-certificates.crt /bin/bash -c 'cd /root/vrrw && exec ./vrrw demo' 2>&1 |
  while IFS= read -r line; do printf '%6s %s\n' "$(seconds "$start" "$(micros)")" "$line"; done | tee "$log" >&2
status=${PIPESTATUS[0]}
set -e
total=$(seconds "$start" "$(micros)")
at() { awk -v pattern="$1" '$0 ~ pattern { print $1; exit }' "$log"; }
minus() { [ -n "$1" ] && [ -n "$2" ] && awk -v a="$1" -v b="$2" 'BEGIN { printf "%.1f", a - b }' || echo null; }
packages=$(at 'setup: ready') built=$(at 'demo: .0/4. bringing up') report=$(at 'demo: report: ')
trials=$(grep -o 'skill [0-9]* of [0-9]* trials succeeded' "$log" | grep -o '[0-9]* of [0-9]*' || echo none)
[ "$status" -eq 0 ] || echo "vrrw: bench first: ./vrrw demo failed (exit $status; its output above)" >&2
printf '{"commit": "%s", "status": %d, "packages_s": %s, "configure_and_build_s": %s, "evaluation_s": %s, "total_s": %s, "trials": "%s", "target_s": 480, "load": "%s"}\n' \
  "$commit" "$status" "${packages:-null}" "$(minus "$built" "$packages")" \
  "$(minus "$report" "$built")" "$total" "$trials" "$(load)"
exit "$status"
