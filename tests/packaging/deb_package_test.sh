#!/usr/bin/env bash
# The Debian package as a user gets it: CPack packs this build's install rules, dpkg -x unpacks
# the .deb into a temporary root, and the installed programs run from a directory outside the
# source and build trees, on the system's Qt. Every check prints what it found when it fails.
# Usage: deb_package_test.sh BUILD_DIR VERSION
set -euo pipefail

build="$1"
version="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
failures=0
fail() {
  echo "FAILED: $*" >&2
  failures=$((failures + 1))
}

cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/out" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log" >&2; echo "FAILED: cpack" >&2; exit 1; }
deb=("$work"/out/fooball_"$version"_*.deb)
[ -f "${deb[0]}" ] || { ls "$work/out" >&2; echo "FAILED: no fooball_${version}_*.deb" >&2; exit 1; }
echo "package: $(basename "${deb[0]}")"

# Depends: the shared libraries dpkg-shlibdeps found, and the plugins and font loaded at run time.
depends="$(dpkg-deb --field "${deb[0]}" Depends)"
for needed in libqt6widgets6 libqt6charts6 libbox2d libchipmunk libbullet libavcodec libavformat \
  libswscale qt6-qpa-plugins fonts-dejavu-core nodejs; do
  [[ "$depends" == *"$needed"* ]] || fail "Depends lacks $needed: $depends"
done

root="$work/root"
dpkg -x "${deb[0]}" "$root"
share="$root/usr/share"
for file in usr/bin/fooball usr/bin/fooball-cli usr/share/applications/fooball.desktop \
  usr/share/icons/hicolor/scalable/apps/fooball.svg \
  usr/share/metainfo/io.github.fooball.FooBall.metainfo.xml \
  usr/share/man/man1/fooball.1.gz usr/share/man/man1/fooball-cli.1.gz \
  usr/share/fooball/js/host.js usr/share/fooball/js/package-lock.json \
  usr/share/fooball/js/node_modules/matter-js/package.json usr/share/doc/fooball/accuracy.md \
  usr/share/doc/fooball/scenes/standard-gas-2000.json; do
  [ -f "$root/$file" ] || fail "missing $file"
done

# Each PNG icon is as large as the folder it is in says (width and height from the IHDR chunk).
for size in 16 22 24 32 48 64 128 256 512; do
  png="$share/icons/hicolor/${size}x${size}/apps/fooball.png"
  if [ ! -f "$png" ]; then
    fail "missing the ${size} px icon"
    continue
  fi
  read -r width height < <(od -An -tu1 -j16 -N8 "$png" |
    awk '{ print $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }')
  [ "$width x $height" = "$size x $size" ] || fail "the ${size} px icon is $width x $height"
done

desktop-file-validate "$share/applications/fooball.desktop" || fail "desktop-file-validate"
appstreamcli validate --no-net "$share/metainfo/io.github.fooball.FooBall.metainfo.xml" ||
  fail "appstreamcli validate"
grep -q "<release version=\"$version\"" "$share/metainfo/io.github.fooball.FooBall.metainfo.xml" ||
  fail "the metadata's release is not $version"

# Run from an empty directory: nothing may come from the source or build tree.
mkdir "$work/elsewhere"
cd "$work/elsewhere"
for program in fooball fooball-cli; do
  got="$("$root/usr/bin/$program" --version)" || fail "$program --version exited $?"
  [ "$got" = "fooball $version" ] || fail "$program --version printed '$got'"
done

# A second of the gas at the engine's fixed 1/60 s step: its summary must report 60 steps.
summary="$("$root/usr/bin/fooball-cli" run --preset gas --duration 1 2>&1)" ||
  fail "fooball-cli run exited $?: $summary"
grep -Eq '^ *steps: +60$' <<<"$summary" || fail "fooball-cli run's summary: $summary"

# An engine in the Node.js host, from the installed share/fooball/js: the head-on balls meet at
# 1.17 s (exact; every backend counts one collision by 3 s).
summary="$("$root/usr/bin/fooball-cli" run --preset head-on --backend matter --duration 3 2>&1)" ||
  fail "fooball-cli run --backend matter exited $?: $summary"
grep -Eq '^ *ball collisions: +1$' <<<"$summary" || fail "the matter run's summary: $summary"

frames="$(QT_QPA_PLATFORM=offscreen "$root/usr/bin/fooball" --frames 10 2>&1)" ||
  fail "fooball --frames 10 exited $?: $frames"
[[ "$frames" == *"mean frame time"* ]] || fail "fooball --frames 10 printed: $frames"

# A recording, as installed: FFmpeg's libraries and their GIF encoder found at run time.
recorded="$(QT_QPA_PLATFORM=offscreen "$root/usr/bin/fooball" --record "$work/run.gif" --fps 25 \
  --frames 5 --size 320x320 2>&1)" || fail "fooball --record exited $?: $recorded"
[ "$(head -c 6 "$work/run.gif" 2>/dev/null)" = "GIF89a" ] || fail "fooball --record wrote no GIF"

# The man pages hold the programs' own help: an option of each, and every subcommand of the CLI.
zcat "$share/man/man1/fooball.1.gz" | grep -q -- 'reset\\-settings' ||
  fail "fooball.1 lacks --reset-settings"
zcat "$share/man/man1/fooball.1.gz" | grep -q -- '\\-\\-record' || fail "fooball.1 lacks --record"
for subcommand in list run compare capacity tradeoff failure-map; do
  zcat "$share/man/man1/fooball-cli.1.gz" | grep -q "^\.SS \"fooball\\\\-cli $subcommand\"" ||
    zcat "$share/man/man1/fooball-cli.1.gz" | grep -q "^\.SS \"fooball-cli $subcommand\"" ||
    fail "fooball-cli.1 lacks the $subcommand section"
done

if [ "$failures" -ne 0 ]; then
  echo "$failures check(s) failed" >&2
  exit 1
fi
echo "installed package: every check passed"
