#!/usr/bin/env bash
# The .deb of `cpack -G DEB` (cmake/install.cmake) installs and runs: extracted with dpkg -x
# into a scratch root (no system install), its chainbreak prints the version and commit,
# renders a short video from the packaged scenes (through the picture module it finds relative
# to itself), `run` loads none of the render stack, its Python module imports and makes a
# snapshot (through the same module), its man page is there, and its Depends name the runtime
# libraries, not -dev packages.
# Usage: test_deb.sh BUILD_DIR
set -euo pipefail
build=$(cd "$1" && pwd)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

(cd "$build" && cpack -G DEB -B "$scratch/pkg" > "$scratch/cpack.log") || {
  cat "$scratch/cpack.log"
  exit 1
}
deb=$(ls "$scratch"/pkg/chainbreak_*.deb)
depends=$(dpkg-deb -f "$deb" Depends)
echo "Depends: $depends"
for lib in libavcodec libavformat libcairo2 libc6 libstdc++6 libosmesa6 fonts-dejavu-core; do
  grep -q "$lib" <<< "$depends" || { echo "Depends lacks $lib" >&2; exit 1; }
done
if grep -q -- "-dev" <<< "$depends"; then echo "Depends names a -dev package" >&2; exit 1; fi

root="$scratch/root"
dpkg -x "$deb" "$root"
version=$("$root/usr/bin/chainbreak" --version)
echo "$version"
grep -Eq '^chainbreak [0-9.]+ \(commit [0-9a-z-]+\)$' <<< "$version"
test -s "$root/usr/share/man/man1/chainbreak.1"
grep -q '^\.SS render' "$root/usr/share/man/man1/chainbreak.1"

cd "$scratch"
"$root/usr/bin/chainbreak" render "$root/usr/share/chainbreak/scenes/step_pulse.toml" \
  --set integrator.t_end=2 -q l --no-overlay --quiet -o "$scratch/pulse.mp4" > render.out
test -s "$scratch/pulse.mp4"
grep -q '"frames":' "$scratch/pulse.json"
# The picture commands live in a module (src/app/picture_commands.h); run must not load it.
LD_DEBUG=libs "$root/usr/bin/chainbreak" run "$root/usr/share/chainbreak/scenes/step_pulse.toml" \
  --set integrator.t_end=1 --quiet > run.out 2> run.libs
if grep -E 'calling init: .*(libavcodec|libcairo|libOSMesa|chainbreak-pictures)' run.libs; then
  echo "chainbreak run loaded the render stack" >&2
  exit 1
fi

PYTHONPATH="$root/usr/lib/python3/dist-packages" /usr/bin/python3 -c "
import chainbreak, sys
assert chainbreak.__file__.startswith('$root'), chainbreak.__file__
scene = chainbreak.Scene.load('$root/usr/share/chainbreak/scenes/step_pulse.toml')
scene.set('integrator.t_end', 1.0)
print('python', chainbreak.__version__, chainbreak.run(scene).tau[-1])
# snapshot() opens the picture module installed beside the shared core (lib/chainbreak).
print('python snapshot', chainbreak.snapshot(scene, 0.0, size=(64, 48)).shape)
"
echo "deb ok: $deb"
