#!/usr/bin/env bash
# Install the Debian packages listed in the given files that are not installed yet.
# A fast no-op when everything is present: no apt-get is run then (`make deps` twice shows it).
# As root it runs apt-get (with `apt-get update` first); otherwise it prints the exact command
# to run.
# A name counts as installed when dpkg reports that package installed, or an installed package
# provides it (a virtual package, e.g. `awk`): apt-get would have nothing to do for either.
set -euo pipefail
provided=  # the names installed packages provide, one a line; read once, when first needed
is_installed() {
  local status
  # The status is read whole before it is tested: `dpkg-query | grep -q` under pipefail counts
  # a dpkg-query stopped by SIGPIPE (grep done at the first match) as "not installed".
  status=$(dpkg-query -W -f='${Status}\n' "$1" 2>/dev/null) || status=
  [[ "$status" == *"ok installed"* ]] && return 0
  if [ -z "$provided" ]; then
    provided=$(dpkg-query -W -f='${db:Status-Abbrev}|${Provides}\n' 2>/dev/null |
      awk -F'|' '$1 ~ /^[ih]i/ { n = split($2, p, /, */)
                                 for (i = 1; i <= n; i++) { sub(/[ :].*/, "", p[i]); if (p[i] != "") print p[i] } }' |
      sort -u)
    provided=${provided:-(none)}
  fi
  grep -qxF -- "$1" <<<"$provided"
}
missing=()
for list in "$@"; do
  while read -r pkg; do
    [ -n "$pkg" ] || continue
    is_installed "$pkg" || missing+=("$pkg")
  done < <(sed -e 's/#.*//' -e 's/[[:space:]]//g' "$list")
done
[ ${#missing[@]} -eq 0 ] && exit 0
cmd="apt-get install -y --no-install-recommends ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then
  echo "hertzdash: missing Debian packages; run as root:" >&2
  echo "  apt-get update && $cmd" >&2
  exit 1
fi
echo "hertzdash: installing ${missing[*]}" >&2
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
$cmd
