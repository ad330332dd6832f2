"""Ctrl-C, exceptions raised in Python hooks, and the arrays hooks are handed (docs/python.md,
"Interrupts and errors")."""
import contextlib
import signal
import sqlite3
import subprocess
import sys
import textwrap
import time
import traceback

import numpy as np
import pytest

import aco
from conftest import MAP1, SOURCE

sys.path.insert(0, str(SOURCE / "examples" / "python"))
from ant_system import AntSystem  # noqa: E402  (the bridge's example: Ant System in numpy)

SMALL = dict(preset="ant-system", ants=10, iterations=20, threads=1)
# Far more iterations than a run can make before the outer timeout: only an interrupt ends it.
ENDLESS = 100_000_000
OUTER_TIMEOUT_S = 300  # against a hang, not a measure


def interrupted(script, tmp_path, ready=None):
    """Runs `script` in a Python process of its own, sends it SIGINT once it has printed "started"
    (and ready() is true), and returns what it printed after."""
    (tmp_path / "script.py").write_text(textwrap.dedent(script))
    child = subprocess.Popen([sys.executable, str(tmp_path / "script.py")], cwd=tmp_path, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True)
    try:
        assert child.stdout.readline() == "started\n", child.stderr.read()
        waited = time.monotonic()
        while ready is not None and not ready():
            assert child.poll() is None and time.monotonic() - waited < OUTER_TIMEOUT_S, child.stderr.read()
            time.sleep(0.05)
        child.send_signal(signal.SIGINT)
        out, err = child.communicate(timeout=OUTER_TIMEOUT_S)
    finally:
        child.kill()
    assert child.returncode == 0, err
    return out


def test_ctrl_c_stops_a_long_plan_between_iterations_with_keyboard_interrupt(tmp_path):
    # No Python hook: once the main thread is inside plan(), which never returns by itself, only
    # the colony's check between iterations can end it. "started" comes from a watcher thread when
    # it sees plan() on the main thread's stack, so the signal cannot arrive before.
    out = interrupted(f"""
        import sys, threading, time, traceback
        import aco

        def announce(main=threading.main_thread().ident):
            while True:
                frame = sys._current_frames().get(main)
                while frame is not None and frame.f_code.co_name != "plan":
                    frame = frame.f_back
                if frame is not None:
                    print("started", flush=True)
                    return
                time.sleep(0.01)

        threading.Thread(target=announce, daemon=True).start()
        try:
            aco.plan({str(MAP1)!r}, (0, 0), (19, 19), preset="ant-system", iterations={ENDLESS})
        except KeyboardInterrupt as interrupt:
            names = [frame.name for frame in traceback.extract_tb(interrupt.__traceback__)]
            print("KeyboardInterrupt in", "plan" if "plan" in names else names)
        """, tmp_path)
    assert out == "KeyboardInterrupt in plan\n"


def test_ctrl_c_stops_a_plan_with_a_python_hook_after_fewer_iterations_than_asked(tmp_path):
    out = interrupted(f"""
        import aco

        class Counting:
            calls = 0

            def update(self, context, iteration, tau):
                Counting.calls += 1
                if Counting.calls == 1:
                    print("started", flush=True)
                tau *= 0.9

        try:
            aco.plan({str(MAP1)!r}, (0, 0), (19, 19), preset="ant-system", iterations={ENDLESS}, update=Counting())
        except KeyboardInterrupt:
            print("KeyboardInterrupt", Counting.calls)
        """, tmp_path)
    word, calls = out.split()
    assert word == "KeyboardInterrupt" and 1 <= int(calls) < ENDLESS


def test_ctrl_c_stops_a_study_between_trials_keeping_those_finished(tmp_path):
    trials = 10
    (tmp_path / "long.yaml").write_text(textwrap.dedent(f"""\
        name: long
        seed: 3
        repetitions: {trials}
        problems:
          - {{name: down, map: {MAP1}, start: [0, 0], goal: [19, 19]}}
        settings: {{preset: ant-system, ants: 10, iterations: 5000}}
        baseline: {{name: ant system}}
        """))

    def stored():
        if not (tmp_path / "long.db").exists():
            return 0
        with contextlib.closing(sqlite3.connect(tmp_path / "long.db", timeout=OUTER_TIMEOUT_S)) as db:
            try:
                return db.execute("SELECT COUNT(*) FROM runs").fetchone()[0]
            except sqlite3.OperationalError:  # no table yet
                return 0

    out = interrupted("""
        import aco
        print("started", flush=True)
        try:
            aco.run_experiment("long.yaml", "long.db", threads=1, progress=False)
        except KeyboardInterrupt:
            print("KeyboardInterrupt")
        """, tmp_path, ready=lambda: stored() >= 1)
    assert out == "KeyboardInterrupt\n"
    finished = aco.read_database(tmp_path / "long.db")
    assert 1 <= len(finished) < trials and finished["error"].isna().all()
    summary = aco.run_experiment(tmp_path / "long.yaml", tmp_path / "long.db", threads=1, progress=False)
    assert summary["skipped"] == len(finished) and summary["skipped"] + summary["ran"] == trials


def raising(exception):
    class Raising:
        def update(self, context, iteration, tau):
            if context.iteration == 3:
                raise exception
            tau *= 0.9

    return Raising()


@pytest.mark.parametrize("exception", [KeyboardInterrupt, SystemExit(4)])
def test_keyboard_interrupt_and_system_exit_in_a_hook_pass_as_themselves(exception):
    with pytest.raises(BaseException) as raised:
        aco.plan(MAP1, (0, 0), (19, 19), update=raising(exception), seed=1, **SMALL)
    assert type(raised.value) is (exception if isinstance(exception, type) else type(exception))
    assert raised.value.__cause__ is None
    if isinstance(exception, SystemExit):
        assert raised.value.code == 4


def ratio(tau):
    return 1 / (len(tau) - len(tau))


def evaporate(tau):
    tau *= ratio(tau)


def test_an_exception_in_a_hook_is_a_plugin_error_from_it_with_its_whole_traceback():
    class Broken:
        def update(self, context, iteration, tau):
            evaporate(tau)

    with pytest.raises(aco.PluginError) as raised:
        aco.plan(MAP1, (0, 0), (19, 19), update=Broken(), seed=1, **SMALL)
    error = raised.value
    assert isinstance(error, aco.Error) and type(error).__module__ == "aco"
    assert "plugin update/python" in str(error) and "raised ZeroDivisionError" in str(error)
    cause = error.__cause__
    assert type(cause) is ZeroDivisionError
    frames = [frame.name for frame in traceback.extract_tb(cause.__traceback__)]
    assert frames == ["update", "evaporate", "ratio"]
    printed = "".join(traceback.format_exception(error))
    assert "The above exception was the direct cause" in printed and "in ratio" in printed


def test_a_failing_class_constructor_is_a_plugin_error_from_its_exception():
    class Refusing:
        def __init__(self):
            raise RuntimeError("no")

        def update(self, context, iteration, tau):
            pass

    aco._live.refusing = Refusing
    try:
        with pytest.raises(aco.PluginError) as raised:
            aco.plan(MAP1, (0, 0), (19, 19), update="python", update_class="aco._live:refusing", **SMALL)
    finally:
        del aco._live.refusing
    assert type(raised.value.__cause__) is RuntimeError


class Keeping:
    """Keeps what update() is handed, or a view made of it."""

    def __init__(self, keep=lambda context, iteration, tau: (tau, context.graph.costs, iteration.ants[0].nodes)):
        self.keep, self.kept = keep, []

    def update(self, context, iteration, tau):
        tau *= 0.9
        self.kept.append((context.iteration, tau.copy(), self.keep(context, iteration, tau)))


def test_arrays_kept_past_a_hook_hold_their_values_at_the_end_of_the_call_and_refuse_writes():
    keeping = Keeping()
    aco.plan(MAP1, (0, 0), (19, 19), update=keeping, seed=1, **SMALL)
    assert [iteration for iteration, _, _ in keeping.kept] == list(range(SMALL["iterations"]))
    for _, values, (tau, costs, nodes) in keeping.kept:
        assert np.array_equal(tau, values)  # not the engine's memory, reused by the next iteration
        for array in (tau, costs, nodes):
            assert not array.flags.writeable
            with pytest.raises(ValueError, match="read-only"):
                array[0] = 1
    costs = [costs for _, _, (_, costs, _) in keeping.kept]
    assert all(np.array_equal(c, costs[0]) for c in costs) and costs[0].min() >= 1


def test_a_view_made_of_a_handed_array_and_kept_is_refused():
    keeping = Keeping(keep=lambda context, iteration, tau: tau[:10])
    with pytest.raises(aco.PluginError, match=r"update\(\) kept a view made of one of its arrays"):
        aco.plan(MAP1, (0, 0), (19, 19), update=keeping, seed=1, **SMALL)


def test_arrays_of_a_failing_hook_stay_readable_from_its_traceback():
    class Failing:
        def update(self, context, iteration, tau):
            tau *= 0.5
            raise RuntimeError("look at tau")

    with pytest.raises(aco.PluginError) as raised:
        aco.plan(MAP1, (0, 0), (19, 19), update=Failing(), seed=1, **SMALL)
    tb = raised.value.__cause__.__traceback__
    while tb.tb_next:
        tb = tb.tb_next
    tau = tb.tb_frame.f_locals["tau"]  # what %debug shows
    assert not tau.flags.writeable and len(tau) > 0 and np.isfinite(tau).all() and (tau > 0).all()


def test_a_kept_array_leaves_the_run_unchanged():
    plain = aco.plan(MAP1, (0, 0), (19, 19), update="ant_system", seed=2, **SMALL)
    class KeepingAntSystem(AntSystem):
        def update(self, context, iteration, tau):
            result = super().update(context, iteration, tau)
            self.kept = tau
            return result

    kept = aco.plan(MAP1, (0, 0), (19, 19), update=KeepingAntSystem(), seed=2, **SMALL)
    assert kept.json["grid_path"] == plain.json["grid_path"] and kept.json["convergence"] == plain.json["convergence"]
