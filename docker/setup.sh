#!/usr/bin/env bash
# The one setup step of vrrw, used by ./vrrw setup, docker/Dockerfile and CI:
# installs the Debian packages in docker/packages.txt, without their recommended packages (on a bare Debian 12:
# 560 packages and 288 MB to fetch instead of 872 and 444 MB; nothing vrrw runs needs the others), and a venv
# holding xacro; `--tests` adds what only the tests use (./vrrw test passes it), so the first `./vrrw demo` does
# not wait for it.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
export PATH=/usr/bin:/bin:/usr/sbin:/sbin:$PATH
packages=$(grep -v '^#' "$root/docker/packages.txt" | tr -s ' \n' ' ')

missing=()
for p in $packages; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo="sudo"
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

venv="$root/.venv"
if [ ! -x "$venv/bin/xacro" ]; then
  echo "setup: creating $venv with xacro==1.13.3" >&2
  /usr/bin/python3 -m venv --system-site-packages "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check xacro==1.13.3
fi
# rosbags: an independent bag reader, used only by vrrw_demos' recorder test.
if [ "${1:-}" = --tests ] && ! "$venv/bin/python" -c "import rosbags" 2>/dev/null; then
  echo "setup: installing rosbags into $venv (vrrw_demos' test reads bags with it)" >&2
  "$venv/bin/pip" install -q --disable-pip-version-check "rosbags==0.11.9"
fi
echo "setup: ready" >&2
