#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Fetches what the SocketCAN test VM boots: Debian's stock kernel (vmlinuz plus the CAN, vcan and
# virtio-9p modules, nothing else), busybox-static and can-utils. They come from Debian's archive
# with `apt-get download` and are unpacked into CACHE, never installed on this machine.
# Usage: fetch-vm-parts.sh CACHE
set -euo pipefail
cache=${1:?usage: fetch-vm-parts.sh CACHE}
mkdir -p "$cache"
cache=$(cd "$cache" && pwd)
x="$cache/x"
if ls "$x"/boot/vmlinuz-* >/dev/null 2>&1 && [ -x "$x/bin/busybox" ] && [ -x "$x/usr/bin/candump" ]; then
  exit 0
fi

kernel_package() { apt-cache depends linux-image-amd64 2>/dev/null | awk '/Depends: linux-image-[0-9]/{print $2; exit}'; }
kpkg=$(kernel_package)
if [ -z "$kpkg" ]; then  # no package lists yet (fresh machine): read them once
  sudo=""; [ "$(id -u)" -eq 0 ] || sudo=sudo
  $sudo apt-get update -qq
  kpkg=$(kernel_package)
fi
[ -n "$kpkg" ] || { echo "fetch-vm-parts: apt knows no linux-image-*-amd64 behind linux-image-amd64" >&2; exit 1; }

debs="$cache/debs"
rm -rf "$debs" "$x.partial"
mkdir -p "$debs" "$x.partial"
echo "fetch-vm-parts: downloading $kpkg busybox-static can-utils into $debs"
(cd "$debs" && apt-get download -q "$kpkg" busybox-static can-utils) ||
  { echo "fetch-vm-parts: apt-get download failed (is Debian's archive reachable?)" >&2; exit 1; }
for deb in "$debs"/*.deb; do
  case "$deb" in
    */linux-image-*)  # the whole kernel unpacks to ~400 MB: take only what the VM loads
      dpkg-deb --fsys-tarfile "$deb" | tar -x -C "$x.partial" --wildcards './boot/vmlinuz-*' \
        './lib/modules/*/kernel/net/can/*' './lib/modules/*/kernel/drivers/net/can/*' \
        './lib/modules/*/kernel/drivers/virtio/*' './lib/modules/*/kernel/net/9p/*' \
        './lib/modules/*/kernel/fs/9p/*' './lib/modules/*/kernel/fs/netfs/*' './lib/modules/*/kernel/fs/fscache/*' ;;
    *) dpkg-deb -x "$deb" "$x.partial" ;;
  esac
done
rm -rf "$debs" "$x"
mv "$x.partial" "$x"
echo "fetch-vm-parts: $(basename "$(ls "$x"/boot/vmlinuz-*)") ready in $x"
