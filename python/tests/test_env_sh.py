"""tools/env.sh names the interpreter the package was built for, and warns when python3 on the
PATH is another (a pyenv shim, say), whose import of aco or numpy would fail."""
import os
import subprocess

import pytest

from conftest import SOURCE

# What a sanitizer build's module needs in the interpreter (the preset sanitize's ctest sets it:
# tests/CMakeLists.txt), kept in the otherwise bare environment below.
SANITIZER_ENV = {k: v for k, v in os.environ.items()
                 if k in ("LD_PRELOAD", "ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS", "PYTHONMALLOC")}


@pytest.fixture
def preset(build):
    if build.parent != SOURCE / "build":
        pytest.skip("tools/env.sh reads the checkout's build/<preset>")
    return build.name


def source_env_sh(preset, first_on_path, then):
    """Sources tools/env.sh with first_on_path before Debian's folders on the PATH, then runs `then`."""
    return subprocess.run(["bash", "-c", f'. "{SOURCE}/tools/env.sh" && {then}'], capture_output=True, text=True,
                          env={"PATH": f"{first_on_path}:/usr/bin:/bin", "ACO_PRESET": preset, **SANITIZER_ENV})


def test_another_python3_first_on_the_path_is_named_and_the_right_one_given(tmp_path, preset, build):
    built_for = (build / "python-interpreter.txt").read_text().strip()
    fake = tmp_path / "python3"
    fake.write_text("#!/bin/sh\necho 'ModuleNotFoundError: No module named numpy' >&2\nexit 1\n")
    fake.chmod(0o755)
    out = source_env_sh(preset, tmp_path, '"$ACO_PYTHON" -c "import aco; print(aco.__version__)"')
    assert out.returncode == 0, out.stderr
    assert f"python3 on the PATH is {fake}, not {built_for}" in out.stderr
    assert out.stdout.strip() == subprocess.run([built_for, "-c", "import aco; print(aco.__version__)"],
                                                capture_output=True, text=True, check=True).stdout.strip()


def test_no_warning_when_python3_is_the_interpreter_built_for(tmp_path, preset, build):
    built_for = (build / "python-interpreter.txt").read_text().strip()
    (tmp_path / "python3").symlink_to(built_for)
    out = source_env_sh(preset, tmp_path, "true")
    assert out.returncode == 0 and out.stderr == ""
