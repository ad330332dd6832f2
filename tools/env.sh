# Puts this checkout's programs on the PATH and its Python package on PYTHONPATH, for the shell
# that sources it (after tools/demo.sh or tools/test.sh has built them):
#   . tools/env.sh            (ACO_PRESET=debug . tools/env.sh for another build preset)
# The programs are links in build/<preset>/bin to the build tree's binaries, named as installed:
# acoplan, acobench, acosim, aco-plugin-check, aco-new-plugin, aco_mapgen, aco_terraingen, aco_bench.
aco_root=$(cd "$(dirname "${BASH_SOURCE[0]:-$0}")/.." && pwd)
aco_build="$aco_root/build/${ACO_PRESET:-release}"
if [ -x "$aco_build/bin/acoplan" ]; then
  export PATH="$aco_build/bin:$PATH"
  export PYTHONPATH="$aco_build/python${PYTHONPATH:+:$PYTHONPATH}"
else
  echo "tools/env.sh: $aco_build/bin/acoplan is not built yet: run tools/demo.sh or tools/test.sh first" >&2
fi
unset aco_root aco_build
