#!/usr/bin/env bash
# Gradescope's image build and a grading run in a real Ubuntu userland, as Gradescope does them.
#
#   bash tests/gradescope_image.sh [jammy|noble] [psNN]      (make gradescope-image)
#
# Gradescope builds an autograder's image from Ubuntu 22.04 (jammy) or 24.04 (noble) by
# unpacking the zip into /autograder/source and running setup.sh as root; it then runs
# /autograder/run_autograder for every submission, in a Docker container: root, Docker's
# seccomp profile and capabilities, no user namespace. This script does the same on this
# machine: a debootstrap of the release (from archive.ubuntu.com, kept in build/ubuntu-REL),
# the zip of `make gradescope` unpacked in it, then, in a chroot under tests/docker_seccomp.py
# (Docker's constraint), setup.sh (whose last step grades the solved copy and a blank one)
# and run_autograder on the solved problem set handed in by a student. It fails unless the
# image builds, the run grades with the privilege drop and gives full marks.
# Needs root, debootstrap (installed with apt-get when missing), python3-seccomp and the
# network; takes 10-20 minutes (not in CI: the archive is outside its registries).
set -euo pipefail
release=${1:-jammy}
ps=${2:-ps01}
cd "$(dirname "$0")/.."
repo=$PWD
root=$repo/build/ubuntu-$release
say() { echo "gradescope-image: $*"; }
[ "$(id -u)" -eq 0 ] || { say "needs root (debootstrap, chroot)"; exit 2; }
command -v debootstrap >/dev/null || apt-get install -y -q debootstrap
/usr/bin/python3 -c "import seccomp" 2>/dev/null || apt-get install -y -q python3-seccomp

if [ ! -f "$root/.complete" ]; then
    say "debootstrap $release into $root"
    rm -rf "$root"
    script=/usr/share/debootstrap/scripts/$release
    [ -e "$script" ] || script=/usr/share/debootstrap/scripts/gutsy  # Debian's lacks noble's
    debootstrap --variant=minbase --components=main,universe "$release" "$root" \
        http://archive.ubuntu.com/ubuntu "$script" >"$repo/build/debootstrap-$release.log" 2>&1 \
        || { tail -20 "$repo/build/debootstrap-$release.log"; exit 1; }
    touch "$root/.complete"
fi
cp /etc/resolv.conf "$root/etc/resolv.conf"
# the pockets of Docker's ubuntu image, which Gradescope's base image is built from (debootstrap
# writes the release pocket alone: jammy's python3.11-venv is in jammy-updates only)
archive=http://archive.ubuntu.com/ubuntu/
{
    echo "deb $archive $release main restricted universe multiverse"
    echo "deb $archive $release-updates main restricted universe multiverse"
    echo "deb $archive $release-backports main restricted universe multiverse"
    echo "deb http://security.ubuntu.com/ubuntu/ $release-security main restricted universe multiverse"
} >"$root/etc/apt/sources.list"

mounted=()
cleanup() {
    for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do umount -l "${mounted[i]}" || true; done
}
trap cleanup EXIT
for m in proc sys dev dev/pts; do
    mkdir -p "$root/$m"
    case $m in
    proc) mount -t proc proc "$root/proc" ;;
    sys) mount -t sysfs sys "$root/sys" ;;
    *) mount --bind "/$m" "$root/$m" ;;
    esac
    mounted+=("$root/$m")
done

say "the zip of $ps"
rm -rf "$root/autograder" "$repo/build/gradescope-image"
.venv/bin/python -m instructor.grading.gradescope "$ps" --out "$repo/build/gradescope-image"
mkdir -p "$root/autograder/source" "$root/autograder/results" "$root/autograder/submission"
.venv/bin/python -c "import sys, zipfile; zipfile.ZipFile(sys.argv[1]).extractall(sys.argv[2])" \
    "$(ls "$repo"/build/gradescope-image/*.zip)" "$root/autograder/source"
cp "$root/autograder/source/run_autograder" "$root/autograder/run_autograder"
chmod 755 "$root/autograder/source/setup.sh" "$root/autograder/run_autograder"

# A machine whose outgoing HTTPS goes through a proxy with a certificate authority of its own
# (this one's: /usr/local/share/ca-certificates) lends pip its bundle; Gradescope needs none.
cert=()
if compgen -G "/usr/local/share/ca-certificates/*.crt" >/dev/null; then
    mkdir -p "$root/etc/ssl"
    cp /etc/ssl/certs/ca-certificates.crt "$root/etc/ssl/host-bundle.crt"
    cert=(PIP_CERT=/etc/ssl/host-bundle.crt)
fi

in_image() {  # a command in the chroot, as root, under Docker's seccomp and capabilities
    /usr/bin/python3 "$repo/tests/docker_seccomp.py" -- /usr/sbin/chroot "$root" \
        /usr/bin/env -i PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
        HOME=/root LANG=C.UTF-8 "${cert[@]}" /bin/bash -c "$1"
}

say "setup.sh (its self-test grades the solved copy and a blank one)"
in_image "cat /etc/os-release | head -2 && cd /autograder/source && bash ./setup.sh"

say "run_autograder on the solved $ps handed in by a student"
solved=$(cd "$root/autograder/course/source/$ps" && ls ./*.ipynb | head -1)
cp "$root/autograder/course/source/$ps/$solved" "$root/autograder/submission/"
cat >"$root/autograder/submission_metadata.json" <<'EOF'
{"users": [{"email": "alice7@example.edu", "sid": "3031042", "id": 1}]}
EOF
in_image "/autograder/run_autograder"
/usr/bin/python3 - "$root/autograder/results/results.json" <<'EOF'
import json, sys
results = json.load(open(sys.argv[1]))
total = sum(t["max_score"] for t in results["tests"])
print(f"gradescope-image: score {results['score']} of {total}, confinement "
      f"{results['extra_data']['confinement']}")
assert results["score"] == total > 0, results["output"]
assert results["extra_data"]["confinement"] == "privdrop", results["extra_data"]
EOF
say "passed on $(. "$root/etc/os-release" && echo "$PRETTY_NAME")"
