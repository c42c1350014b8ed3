#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Add Debian's bookworm-backports suite as an apt source (KiCad 9 lives there), using the same mirror
# as the machine's main debian.sources stanza. Idempotent: does nothing when a backports source exists.
# Packages from backports are only installed when asked for with `-t bookworm-backports`.
set -euo pipefail

sources_dir=/etc/apt/sources.list.d
main_sources=$sources_dir/debian.sources
target=$sources_dir/backports.sources

if grep -rqs 'bookworm-backports' /etc/apt/sources.list "$sources_dir"; then
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "enable-backports: need root or sudo to write $target" >&2; exit 1; }
  sudo="sudo"
fi

if [ -f "$main_sources" ]; then
  # The first deb822 stanza is the main archive; keep its URIs and keyring, swap the suite.
  stanza=$(awk 'BEGIN{RS="";ORS="\n"} NR==1' "$main_sources" | sed 's/^Suites:.*/Suites: bookworm-backports/')
  grep -q '^Suites: bookworm-backports$' <<<"$stanza" \
    || { echo "enable-backports: no Suites line in the first stanza of $main_sources" >&2; exit 1; }
else
  # One-line sources.list machines: take the mirror of the first plain bookworm entry.
  mirror=$(awk '$1=="deb" && $3=="bookworm" {print $2; exit}' /etc/apt/sources.list 2>/dev/null || true)
  [ -n "$mirror" ] || { echo "enable-backports: found neither $main_sources nor a bookworm line in /etc/apt/sources.list" >&2; exit 1; }
  stanza=$(printf 'Types: deb\nURIs: %s\nSuites: bookworm-backports\nComponents: main\nSigned-By: /usr/share/keyrings/debian-archive-keyring.gpg\n' "$mirror")
fi

echo "enable-backports: writing $target"
printf '%s\n' "$stanza" | $sudo tee "$target" >/dev/null
$sudo apt-get update -qq
