#!/usr/bin/env bash
# One-step set-up: install every Debian package the workspace uses, then build it
# with Debian's /usr/bin/python3 (never a pyenv interpreter). Idempotent and quiet
# when everything is already present.
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
cd "$here"

shopt -s nullglob
lists=(scripts/debian-packages.txt catkin_ws/src/*/debian-packages.txt)
wanted=$(cat "${lists[@]}" \
  | sed 's/#.*//' | tr -s ' \t' '\n' | sed '/^$/d' | sort -u)
missing=()
for pkg in $wanted; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q "install ok installed" || missing+=("$pkg")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  export DEBIAN_FRONTEND=noninteractive
  # Wait for another apt (a fresh machine's unattended upgrades, a second checkout's set-up)
  # rather than failing on its lock.
  wait_for_lock=(-o DPkg::Lock::Timeout=900)
  $sudo_cmd apt-get "${wait_for_lock[@]}" update -qq
  $sudo_cmd apt-get "${wait_for_lock[@]}" install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

exec "$here/scripts/build.sh"
