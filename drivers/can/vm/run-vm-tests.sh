#!/usr/bin/env bash
# SPDX-FileCopyrightText: 2026 Robogene contributors
# SPDX-License-Identifier: BSD-3-Clause
#
# Runs the CAN tests against a real Linux SocketCAN stack. This machine's kernel may have no CAN,
# so it boots Debian's stock kernel under qemu (KVM when usable, else software emulation) with a
# busybox initramfs that loads can, can-raw and vcan, creates vcan0 (up) and vcandown (left down),
# mounts this machine's / read-only over virtio-9p and OUT read-write, and runs in-vm-tests.sh in
# a chroot of it, so the tests are the very binaries BUILD holds. Results come back on the serial
# console (printed here and kept in OUT/console.log); candump-format logs land in OUT.
#
# Usage: run-vm-tests.sh --build BUILD --cache CACHE --out OUT [--timeout SECONDS]
#   BUILD: the CMake build dir (bin/robogene_can_tests, bin/robogene); CACHE: fetch-vm-parts.sh's.
# Env: ACCEL=auto|kvm|tcg (auto: KVM only on a host with usable VMX/SVM KVM), MEM=512 (MiB).
# Exit: 0 when every in-VM test passed; 1 with a message saying what failed (qemu missing, no boot,
# timeout, tests failed).
set -euo pipefail

here=$(cd "$(dirname "$0")" && pwd)
repo=$(cd "$here/../../.." && pwd)
build="" cache="" out="" timeout_s=240
while [ $# -gt 0 ]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --cache) cache=$2; shift 2 ;;
    --out) out=$2; shift 2 ;;
    --timeout) timeout_s=$2; shift 2 ;;
    *) echo "run-vm-tests: unknown argument $1" >&2; exit 2 ;;
  esac
done
[ -n "$build" ] && [ -n "$cache" ] && [ -n "$out" ] || { echo "usage: $0 --build BUILD --cache CACHE --out OUT" >&2; exit 2; }
die() { echo "run-vm-tests: $*" >&2; exit 1; }

command -v qemu-system-x86_64 >/dev/null || die "qemu-system-x86_64 not found (Debian package qemu-system-x86, listed in tools/setup/apt/can.txt)"
build=$(cd "$build" && pwd) || die "no build dir"
[ -x "$build/bin/robogene_can_tests" ] || die "$build/bin/robogene_can_tests is missing: build the project first"
"$here/fetch-vm-parts.sh" "$cache"
cache=$(cd "$cache" && pwd)
mkdir -p "$out"
out=$(cd "$out" && pwd)
rm -f "$out"/*.log "$out"/*.xml

x="$cache/x"
kernel=$(ls "$x"/boot/vmlinuz-* | head -1)
kver=${kernel##*/vmlinuz-}
mods="$x/lib/modules/$kver/kernel"

# ---- initramfs: busybox, iproute2's ip (busybox's cannot add a vcan link), the modules, /init
root="$out/initramfs.d"
rm -rf "$root"
mkdir -p "$root"/{bin,sbin,usr/sbin,lib/modules,proc,sys,dev,tmp,mnt/host}
cp "$x/bin/busybox" "$root/bin/busybox"
for a in sh mount insmod mkdir cat echo poweroff chroot sleep; do ln -s busybox "$root/bin/$a"; done
cp /usr/sbin/ip "$root/usr/sbin/ip"
ldd /usr/sbin/ip | awk '$2 == "=>" && $3 ~ /^\// {print $3} $1 ~ /^\// {print $1}' | while read -r lib; do
  mkdir -p "$root$(dirname "$lib")"
  cp -L "$lib" "$root$lib"
done
# Load order matters: there is no modules.dep, so dependencies come first.
modules="drivers/net/can/dev/can-dev.ko drivers/net/can/vcan.ko net/can/can.ko net/can/can-raw.ko
  drivers/virtio/virtio_ring.ko drivers/virtio/virtio.ko drivers/virtio/virtio_pci_modern_dev.ko
  drivers/virtio/virtio_pci_legacy_dev.ko drivers/virtio/virtio_pci.ko net/9p/9pnet.ko net/9p/9pnet_virtio.ko
  fs/netfs/netfs.ko fs/fscache/fscache.ko fs/9p/9p.ko"
load=""
for m in $modules; do
  [ -f "$mods/$m" ] || die "kernel $kver has no module $m"
  cp "$mods/$m" "$root/lib/modules/"
  load="$load $(basename "$m")"
done
cat > "$root/init" <<INIT
#!/bin/sh
mount -t proc proc /proc; mount -t sysfs sys /sys; mount -t devtmpfs dev /dev; mount -t tmpfs tmp /tmp
echo "ROBOGENE_CAN_VM_BOOTED \$(cat /proc/uptime)"
rc=0
for m in $load; do insmod /lib/modules/\$m || { echo "ROBOGENE_CAN_VM: insmod \$m failed"; rc=90; }; done
IP=/usr/sbin/ip   # by path: busybox sh would run its own ip applet
\$IP link set lo up
\$IP link add dev vcan0 type vcan && \$IP link set up vcan0 || rc=91
\$IP link add dev vcandown type vcan || rc=91
\$IP -brief link show
H=/mnt/host
mount -t 9p -o trans=virtio,version=9p2000.L,msize=262144,cache=loose,ro hostroot \$H || rc=92
for d in proc sys dev; do mount --bind /\$d \$H/\$d; done
mount -t tmpfs run \$H/run   # the only writable place besides OUT (TMPDIR)
mount -t 9p -o trans=virtio,version=9p2000.L,msize=262144 out "\$H$out" || rc=93
if [ \$rc -eq 0 ]; then
  chroot \$H /usr/bin/env -i PATH=/usr/local/bin:/usr/bin:/bin:/usr/sbin:/sbin HOME=/run TMPDIR=/run \
    /bin/sh "$here/in-vm-tests.sh" "$build" "$out" "$x/usr/bin" || rc=\$?
fi
echo "ROBOGENE_CAN_VM_RC=\$rc"
poweroff -f
INIT
chmod +x "$root/init"
(cd "$root" && find . | cpio -o -H newc --quiet | gzip -1 > "$out/initramfs.gz")
rm -rf "$root"

# ---- boot
accel=${ACCEL:-auto}
if [ "$accel" = auto ]; then
  # This workplace's /dev/kvm is kvm_pvm, which cannot run a stock kernel: use TCG there.
  if [ -d /sys/module/kvm_pvm ] || ! [ -w /dev/kvm ] || ! grep -qwE 'vmx|svm' /proc/cpuinfo; then accel=tcg; else accel=kvm; fi
fi
if [ "$accel" = kvm ]; then accel_args=(-enable-kvm -cpu host); else accel_args=(-accel tcg -cpu max); fi
echo "run-vm-tests: booting Linux $kver under qemu ($accel), timeout ${timeout_s}s"
start=$(date +%s)
set +e
timeout --kill-after=5 "$timeout_s" qemu-system-x86_64 "${accel_args[@]}" -m "${MEM:-512}" -smp 1 \
  -nographic -no-reboot -nodefaults -serial stdio -kernel "$kernel" -initrd "$out/initramfs.gz" \
  -append "console=ttyS0 quiet loglevel=3 panic=-1 mitigations=off" \
  -virtfs "local,path=/,mount_tag=hostroot,security_model=none,readonly=on,multidevs=remap" \
  -virtfs "local,path=$out,mount_tag=out,security_model=none,multidevs=remap" \
  </dev/null 2>&1 | tee "$out/console.log"
qemu_rc=${PIPESTATUS[0]}
set -e
echo "run-vm-tests: qemu exited with $qemu_rc after $(( $(date +%s) - start ))s"

timed_out=0
if [ "$qemu_rc" -eq 124 ] || [ "$qemu_rc" -eq 137 ]; then timed_out=1; fi
if ! grep -q 'ROBOGENE_CAN_VM_BOOTED' "$out/console.log"; then
  [ $timed_out = 1 ] && die "the VM's kernel did not reach /init within ${timeout_s}s (a hang at boot?); see $out/console.log"
  die "the VM's kernel never reached /init (qemu exit $qemu_rc); see $out/console.log"
fi
[ $timed_out = 1 ] && die "the VM booted but did not finish its tests within ${timeout_s}s; see $out/console.log"
vm_rc=$(sed -n 's/.*ROBOGENE_CAN_VM_RC=\([0-9]*\).*/\1/p' "$out/console.log" | tail -1)
[ -n "$vm_rc" ] || die "the VM stopped without reporting a result (qemu exit $qemu_rc); see $out/console.log"
case "$vm_rc" in
  0) echo "run-vm-tests: every SocketCAN test passed inside the VM; logs in $out" ;;
  9[0-3]) die "the VM could not set up CAN or the shared folders (code $vm_rc); see $out/console.log" ;;
  *) die "SocketCAN tests failed inside the VM (code $vm_rc); see $out/console.log" ;;
esac
