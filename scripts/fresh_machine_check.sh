#!/usr/bin/env bash
# Proves the README's quick start on a fresh Debian 12: bootstraps a minimal root
# (debootstrap --variant=minbase bookworm), puts a clean clone of HEAD and a copy of ../shared
# into it and runs `make demo`, then `make test`, inside it with chroot. Prints each step's
# wall time and exit code. Run as root: scripts/fresh_machine_check.sh
#
# The host keeps whatever packages were installed before, so only a fresh root shows a missing
# install step. The bootstrapped root (minbase only, nothing of the project's) is cached as a
# tarball in $TWINPATH_FRESH_CACHE (default /var/cache/twinpath-fresh-root); delete it to
# bootstrap again. The mirror and any proxy come from this machine's apt configuration.
set -euo pipefail

suite=bookworm
repo=$(git -C "$(dirname "$0")/.." rev-parse --show-toplevel)
cache_dir=${TWINPATH_FRESH_CACHE:-/var/cache/twinpath-fresh-root}

die() { echo "fresh-machine-check: $*" >&2; exit 2; }
say() { echo "fresh-machine-check: $*"; }

[[ $(id -u) -eq 0 ]] || die "must run as root (debootstrap, mount and chroot need it)"
[[ -d $repo/../shared ]] || die "no ../shared beside $repo (the tests read its meshes)"
# The physical path: ../shared may be a symbolic link, and the root needs its contents.
shared=$(cd "$repo/../shared" && pwd -P)
head=$(git -C "$repo" rev-parse HEAD)
git -C "$repo" diff --quiet HEAD ||
  say "warning: uncommitted changes in $repo are not checked (only commit $head is)"
arch=$(dpkg --print-architecture)
cache=$cache_dir/$suite-$arch-minbase.tar

# This machine's Debian repositories for the suite and its updates/security suites, as apt
# resolved them, one "URI SUITE COMPONENT" line each; the first is the main archive.
# shellcheck disable=SC2016 # $(...) are apt's format fields, not shell.
repos=$(apt-get indextargets --format '$(REPO_URI) $(RELEASE) $(COMPONENT)' \
  "Created-By: Packages" | sort -u | awk -v s="$suite" '$2 == s || index($2, s "-") == 1')
mirror=$(awk -v s="$suite" '$2 == s { print $1; exit }' <<<"$repos")
[[ -n $mirror ]] || die "this machine's apt sources have no '$suite' repository to bootstrap from"
# Proxy and validity settings of this machine's apt, for the root's apt and for debootstrap.
apt_conf=$(apt-config dump | grep -E '^Acquire::(https?|ftp)::Proxy|^Acquire::Check-(Valid-Until|Date)' || true)
proxy=$(apt-config dump --format '%v' Acquire::http::Proxy 2>/dev/null || true)
if [[ -n $proxy && -z ${http_proxy:-} ]]; then export http_proxy=$proxy; fi

work=$(mktemp -d /var/tmp/twinpath-fresh.XXXXXX)
root=$work/root
mounts=(proc sys sys/fs/cgroup dev dev/pts dev/shm)

# Processes still running inside the root (a hung test, a daemon a package started) keep its
# mounts busy. SIGKILL is asynchronous: repeat until none is left (10 s at most).
kill_root_processes() {
  local pid link try found
  for ((try = 0; try < 20; try++)); do
    found=0
    for pid in /proc/[0-9]*; do
      link=$(readlink "$pid/root" 2>/dev/null) || continue
      if [[ $link == "$root" || $link == "$root"/* ]]; then
        found=1
        kill -9 "${pid#/proc/}" 2>/dev/null || true
      fi
    done
    ((found)) || return 0
    sleep 0.5
  done
}

# Runs on every exit (success, failure, SIGINT, SIGTERM): unmounts in reverse order and removes
# the root only when nothing is mounted under it any more (rm stays on the root's file system
# besides).
cleanup() {
  local rc=$? i m
  trap - EXIT INT TERM
  kill_root_processes
  for ((i = ${#mounts[@]} - 1; i >= 0; i--)); do
    m=$root/${mounts[i]}
    if mountpoint -q "$m"; then umount -R "$m" || umount -l "$m" || true; fi
  done
  if findmnt -rn -o TARGET | grep -q "^$root/"; then
    echo "fresh-machine-check: still mounted, left $work in place:" >&2
    findmnt -rn -o TARGET | grep "^$root/" >&2
    rc=3
  else
    rm -rf --one-file-system "$work"
  fi
  exit "$rc"
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
trap 'echo "fresh-machine-check: failed at line $LINENO: $BASH_COMMAND" >&2' ERR

summary=()
# The step table, then ctest's closing lines (its verdict and any failed tests) last, where CI
# reads them.
print_summary() {
  printf '%s\n' "${summary[@]}"
  [[ ! -f $work/make-test.log ]] || sed -n '/tests passed, /,$p' "$work/make-test.log"
}

# step NAME CMD...: runs CMD in the background (so that a signal interrupts the wait), prints
# its wall time and exit code, and stops the check when it fails.
step() {
  local name=$1 start rc=0
  shift
  say "== $name =="
  start=$(date +%s)
  "$@" &
  wait $! || rc=$?
  summary+=("$(printf '%-28s %5d s  exit %d' "$name" $(($(date +%s) - start)) "$rc")")
  say "$name: $(($(date +%s) - start)) s, exit $rc"
  if [[ $rc -ne 0 ]]; then
    print_summary
    die "$name failed (exit $rc)"
  fi
}

in_root() {
  chroot "$root" /usr/bin/env -i HOME=/root LANG=C.UTF-8 TERM=dumb CI="${CI:-}" \
    PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
    ${http_proxy:+http_proxy="$http_proxy"} ${https_proxy:+https_proxy="$https_proxy"} "$@"
}

bootstrap() {
  command -v debootstrap >/dev/null || {
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq debootstrap
  }
  debootstrap --variant=minbase "$suite" "$root" "$mirror"
  # Cached before anything else goes in: the tarball holds the minbase system only.
  mkdir -p "$cache_dir"
  tar -C "$root" --numeric-owner -cf "$cache.part" .
  mv "$cache.part" "$cache"
}

restore() {
  mkdir "$root"
  tar -C "$root" --numeric-owner -xpf "$cache"
}

# This machine's repositories, proxy and DNS, so that the root's apt reaches the same mirror.
configure_root() {
  rm -f "$root/etc/apt/sources.list"
  awk '{ print "deb " $1 " " $2 " " $3 }' <<<"$repos" >"$root/etc/apt/sources.list"
  printf '%s\n' "$apt_conf" >"$root/etc/apt/apt.conf.d/99fresh-machine-check"
  cp -L /etc/resolv.conf "$root/etc/resolv.conf"
  # No package may start a daemon inside the root: it would outlive the check and keep the
  # mounts busy (the usual policy-rc.d of chroots and containers).
  printf '#!/bin/sh\nexit 101\n' >"$root/usr/sbin/policy-rc.d"
  chmod 755 "$root/usr/sbin/policy-rc.d"
  mkdir -p "$root/work"
  git clone -q --no-checkout "$repo" "$root/work/twinpath"
  git -C "$root/work/twinpath" checkout -q --detach "$head"
  mkdir "$root/work/shared"
  cp -a "$shared/." "$root/work/shared/"
  mount -t proc proc "$root/proc"
  mount -t sysfs sysfs "$root/sys"
  # A booted Debian machine has its cgroup hierarchy mounted (systemd does it); slurmd, which the
  # farm test starts, refuses to run without it. A slave copy: nothing done inside the root
  # propagates back to the host's mounts.
  if mountpoint -q /sys/fs/cgroup; then
    mount --rbind /sys/fs/cgroup "$root/sys/fs/cgroup"
    mount --make-rslave "$root/sys/fs/cgroup"
  fi
  mount_dev
}

# The root gets a /dev of its own (a tmpfs with the usual nodes, a private devpts instance and
# shared memory for Chromium) rather than a bind of the host's: nothing a package script or a
# killed dpkg does inside the root can then replace or delete the host's device nodes.
mount_dev() {
  local node name major minor
  mount -t tmpfs -o mode=755,size=16m,nosuid tmpfs "$root/dev"
  for node in "null 1 3" "zero 1 5" "full 1 7" "random 1 8" "urandom 1 9" "tty 5 0"; do
    read -r name major minor <<<"$node"
    mknod -m 666 "$root/dev/$name" c "$major" "$minor"
  done
  ln -s /proc/self/fd "$root/dev/fd"
  ln -s /proc/self/fd/0 "$root/dev/stdin"
  ln -s /proc/self/fd/1 "$root/dev/stdout"
  ln -s /proc/self/fd/2 "$root/dev/stderr"
  mkdir "$root/dev/pts" "$root/dev/shm"
  mount -t devpts -o newinstance,ptmxmode=0666,mode=620 devpts "$root/dev/pts"
  ln -s pts/ptmx "$root/dev/ptmx"
  mount -t tmpfs -o mode=1777,size=2g,nosuid,nodev tmpfs "$root/dev/shm"
}

# make test, its output also kept (pipefail is on) for print_summary.
run_tests() { in_root make -C /work/twinpath test 2>&1 | tee "$work/make-test.log"; }

say "commit $head, mirror $mirror, root $root"
if [[ -f $cache ]]; then
  step "restore minbase root" restore
else
  step "debootstrap minbase" bootstrap
fi
configure_root
# The quick start assumes make (README); everything else make demo and make test install.
step "install make" in_root sh -c 'apt-get update -qq &&
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends make >/dev/null'
step "make demo" in_root make -C /work/twinpath demo
step "make test" run_tests

say "all steps passed:"
print_summary
