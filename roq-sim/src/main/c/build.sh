#!/usr/bin/env bash
# Builds libroqsim.so (the joint loop) against MuJoCo 2.2.2. Called by Maven at process-classes:
#   build.sh SRC_DIR OUT_DIR      (OUT_DIR/include holds the JNI header javac -h wrote)
set -euo pipefail
src=$1
out=$2
missing=()
command -v gcc >/dev/null 2>&1 || missing+=("gcc (not on the PATH)")
[ -f /usr/include/mujoco/mujoco.h ] || missing+=("libmujoco-dev (no /usr/include/mujoco/mujoco.h)")
if [ ${#missing[@]} -gt 0 ]; then
  # As root (CI, a fresh container), install them as .ci/run does for Xvfb; otherwise say the one command.
  if [ "$(id -u)" = 0 ] && command -v apt-get >/dev/null 2>&1; then
    echo "roq-sim: installing gcc libmujoco-dev (missing ${missing[*]}) ..." >&2
    { DEBIAN_FRONTEND=noninteractive apt-get update -qq && DEBIAN_FRONTEND=noninteractive \
        apt-get install -y -qq --no-install-recommends gcc libmujoco-dev; } >/dev/null
  else
    echo "roq-sim: cannot build the native joint loop: missing ${missing[*]}; install with: sudo apt-get install -y gcc libmujoco-dev" >&2
    exit 1
  fi
fi
java_home=${JAVA_HOME:-$(dirname "$(dirname "$(readlink -f "$(command -v javac)")")")}
mkdir -p "$out"
lib="$out/libroqsim.so"
# Rebuild only when a source, header or the JNI header is newer than the library.
if [ -f "$lib" ] && [ -z "$(find "$src" "$out/include" -newer "$lib" -type f -print -quit)" ]; then
  exit 0
fi
gcc -std=gnu11 -O2 -g -fPIC -shared -Wall -Wextra -Werror -Wno-unused-parameter \
    -I"$java_home/include" -I"$java_home/include/linux" -I"$out/include" -I"$src" \
    -o "$lib.tmp" "$src"/roq_model.c "$src"/roq_tick.c "$src"/roq_ray.c "$src"/roq_loop.c "$src"/roq_jni.c -lmujoco -lpthread -lm
mv "$lib.tmp" "$lib"
