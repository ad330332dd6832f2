# Puts this checkout's programs on the PATH and its Python package on PYTHONPATH, for the shell
# that sources it (after tools/demo.sh or tools/test.sh has built them):
#   . tools/env.sh            (ACO_PRESET=debug . tools/env.sh for another build preset)
# The programs are links in build/<preset>/bin to the build tree's binaries, named as installed:
# acoplan, acobench, acosim, aco-plugin-check, aco-new-plugin, aco_mapgen, aco_terraingen, aco_bench.
# ACO_PYTHON is the interpreter the package was built for (Debian's /usr/bin/python3, whose numpy
# and pandas it uses); a warning says so when python3 on the PATH is another (pyenv, conda).
aco_root=$(cd "$(dirname "${BASH_SOURCE[0]:-$0}")/.." && pwd)
aco_build="$aco_root/build/${ACO_PRESET:-release}"
if [ -x "$aco_build/bin/acoplan" ]; then
  export PATH="$aco_build/bin:$PATH"
  export PYTHONPATH="$aco_build/python${PYTHONPATH:+:$PYTHONPATH}"
  if [ -f "$aco_build/python-interpreter.txt" ]; then
    ACO_PYTHON=$(cat "$aco_build/python-interpreter.txt")
    export ACO_PYTHON
    aco_path_python=$(command -v python3 || true)
    if [ -z "$aco_path_python" ] || [ "$(readlink -f "$aco_path_python")" != "$(readlink -f "$ACO_PYTHON")" ]; then
      echo "tools/env.sh: python3 on the PATH is ${aco_path_python:-missing}, not $ACO_PYTHON, which the aco" \
           "package was built for (import aco needs it and its numpy): run $ACO_PYTHON, or \"\$ACO_PYTHON\"" >&2
    fi
    unset aco_path_python
  fi
else
  echo "tools/env.sh: $aco_build/bin/acoplan is not built yet: run tools/demo.sh or tools/test.sh first" >&2
fi
unset aco_root aco_build
