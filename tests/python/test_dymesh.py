"""The Python module `dymesh` (issue 10): scenario runs, bodies and summary, views that keep their run
alive, errors as exceptions, and the force-provider loop. Run by ctest with PYTHONPATH=build/python;
DYMESH_DATA_DIR and DYMESH_CLI name the data folder and the command."""
import gc
import json
import os
import pathlib
import signal
import subprocess
import tempfile
import threading
import unittest

import numpy as np

import dymesh

DATA = os.environ["DYMESH_DATA_DIR"]
CLI = os.environ["DYMESH_CLI"]
BARRIER = os.path.join(DATA, "scenarios", "barrier_frontal.json")


class ScenarioRun(unittest.TestCase):
    def test_summary_is_byte_identical_to_the_command(self):
        with tempfile.TemporaryDirectory() as out:
            subprocess.run([CLI, "run", BARRIER, "--quiet", "--out", out], check=True)
            with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
                expected = f.read()
        run = dymesh.load_scenario(BARRIER).run()
        self.assertEqual(run.summary_json, expected)
        self.assertEqual(run.summary, json.loads(expected))
        self.assertEqual(run.status, "complete")

    def test_bodies_delta_v_and_crush(self):
        run = dymesh.load_scenario(BARRIER).run()
        self.assertEqual([b.name for b in run.bodies], ["p406", "barrier"])
        car = run.bodies[0]
        # the demo's 33.0 mph into the barrier, all along x (US scenario: mph)
        self.assertAlmostEqual(car.delta_v[0], run.summary["bodies"][0]["delta_v_earth"][0], places=12)
        self.assertLess(car.delta_v[0], -30.0)
        self.assertEqual(car.crush.shape, (4383,))
        self.assertAlmostEqual(car.crush.max() / 0.0254, run.summary["bodies"][0]["max_crush"], places=9)

    def test_views_are_read_only_and_keep_their_run_alive(self):
        run = dymesh.load_scenario(BARRIER)
        vertices = run.bodies[0].vertices
        deformation = run.body(0).deformation
        before = vertices.copy()
        self.assertEqual(vertices.shape, (4383, 3))
        self.assertFalse(vertices.flags.writeable)
        with self.assertRaises(ValueError):
            vertices[0, 0] = 1.0
        run.run()
        # the view follows the run: the crushed front moved back by the deformation
        moved = np.abs(vertices - before).max()
        self.assertGreater(moved, 0.4)
        del run
        gc.collect()
        self.assertTrue(np.isfinite(vertices).all())  # the run is still alive through the view
        self.assertAlmostEqual(np.linalg.norm(deformation, axis=1).max(), moved, delta=0.05)


class ScenarioFromPython(unittest.TestCase):
    def test_a_dict_runs_as_its_file_does_and_takes_changes(self):
        with open(BARRIER, encoding="utf-8") as f:
            spec = json.load(f)
        base = os.path.dirname(BARRIER)
        same = dymesh.scenario(spec, base).run()
        # byte-identical but for the scenario's name, which is the base folder's "(python scenario)"
        expected = dymesh.load_scenario(BARRIER).run().summary_json
        self.assertEqual(same.summary_json.replace("(python scenario)", "barrier_frontal.json"), expected)
        spec["bodies"][0]["initial"]["speed"] = 20.0
        slower = dymesh.scenario(json.dumps(spec), base).run()
        self.assertAlmostEqual(slower.summary["overall"]["closing_speed"], 20.0, delta=0.05)

    def test_a_bad_dict_names_the_field(self):
        with open(BARRIER, encoding="utf-8") as f:
            spec = json.load(f)
        spec["bodies"][0]["motion"] = "flying"
        with self.assertRaisesRegex(dymesh.InputError, r"bodies\[0\]\.motion"):
            dymesh.scenario(spec, os.path.dirname(BARRIER))
        # a NaN (json.dumps writes it as NaN, refused before only as malformed JSON at a byte offset)
        spec["bodies"][0]["motion"] = "planar"
        spec["bodies"][0]["initial"]["speed"] = float("nan")
        with self.assertRaisesRegex(dymesh.InputError, r"bodies\[0\]\.initial\.speed: expected a finite number, got nan"):
            dymesh.scenario(spec, os.path.dirname(BARRIER))

    def test_a_dict_that_is_no_json_tree_is_refused_naming_the_path(self):
        # a sweep of the module, 2026-11-28: a dict holding itself, or a value nested 100,000 deep,
        # crashed the interpreter (the non-finite check recursed without end)
        spec = {"name": "x"}
        spec["self"] = spec
        with self.assertRaisesRegex(ValueError, r"self: refers back to a value that holds it"):
            dymesh.scenario(spec)
        shared = {"b": [1.0, 2.0]}
        with self.assertRaisesRegex(dymesh.InputError, r"\(root\): expected an object|unknown key"):
            dymesh.scenario([shared, shared])  # the same list twice is no cycle: the scenario's own checks speak
        deep = []
        inner = deep
        for _ in range(100000):
            inner.append([])
            inner = inner[0]
        with self.assertRaisesRegex(ValueError, r"name(\[0\]){200}: expected values nested at most 200 deep"):
            dymesh.scenario({"name": deep})
        # a name Python cannot give as UTF-8 (a lone surrogate) is named, not a byte offset of the JSON text
        with open(BARRIER, encoding="utf-8") as f:
            spec = json.load(f)
        spec["bodies"][0]["name"] = "car\udcff"
        with self.assertRaisesRegex(dymesh.InputError, r"bodies\[0\]\.name: expected UTF-8 text"):
            dymesh.scenario(spec, os.path.dirname(BARRIER))

    def test_paths_may_be_path_objects(self):
        # os.PathLike, as open() takes (a pathlib.Path was a TypeError listing pybind11's signatures)
        base = pathlib.Path(BARRIER).parent
        run = dymesh.load_scenario(pathlib.Path(BARRIER))
        with open(BARRIER, encoding="utf-8") as f:
            self.assertEqual(dymesh.scenario(json.load(f), base).bodies[0].name, run.bodies[0].name)
        run.run()
        with tempfile.TemporaryDirectory() as out:
            run.write_outputs(pathlib.Path(out) / "outputs")
            self.assertTrue((pathlib.Path(out) / "outputs" / "summary.json").is_file())
        with self.assertRaisesRegex(TypeError, "path: expected str, bytes or os.PathLike"):
            dymesh.load_scenario(5)


class Errors(unittest.TestCase):
    def test_engine_messages_become_exceptions(self):
        with self.assertRaises(dymesh.InputError) as refused:
            dymesh.load_scenario("/nonexistent/scenario.json")
        self.assertIn("file not found", str(refused.exception))
        self.assertTrue(issubclass(dymesh.InputError, ValueError))
        run = dymesh.load_scenario(BARRIER)
        with self.assertRaises(IndexError):
            run.body(2)
        with self.assertRaisesRegex(ValueError, r"shape \(2, 12\)"):
            run.host_step(np.zeros((1, 12)), 0.0005)
        with self.assertRaisesRegex(ValueError, "dt must be finite and > 0"):
            run.host_step(run.states(), 0.0)
        bad = run.states()
        bad[0, 6] = np.nan
        with self.assertRaisesRegex(ValueError, "non-finite"):
            run.host_step(bad, 0.0005)

    def test_arguments_of_the_wrong_kind(self):
        # a sweep of the module, 2026-11-28: dt=True was taken as a step of 1 s; 2**40 threads raised
        # pybind11's TypeError listing signatures
        run = dymesh.load_scenario(BARRIER)
        with self.assertRaisesRegex(TypeError, "dt: expected a number of seconds, got bool"):
            run.host_step(run.states(), True)
        with self.assertRaisesRegex(TypeError, "dt: expected a number of seconds, got bool"):
            run.host_step(run.states(), np.True_)
        self.assertEqual(run.time, 0.0)
        run.host_step(run.states(), np.float64(0.0005))  # a numpy number is a number
        with self.assertRaisesRegex(ValueError, r"threads: expected 0 \(all cores\) \.\. 4096, got 1099511627776"):
            dymesh.set_threads(2 ** 40)
        with self.assertRaisesRegex(ValueError, r"threads: expected 0 \(all cores\) \.\. 4096, got -1"):
            dymesh.set_threads(-1)
        with self.assertRaisesRegex(TypeError, "threads: expected an int"):
            dymesh.set_threads(2.0)
        dymesh.set_threads(0)


class RunState(unittest.TestCase):
    # found by a fuzz of the library, 2026-11-28: a finished run stepped on, a host-driven run given a
    # step of its own, and a path cut short at a NUL were all accepted
    def test_a_run_is_driven_one_way_and_ends_once(self):
        self.assertTrue(issubclass(dymesh.StateError, RuntimeError))
        run = dymesh.load_scenario(BARRIER).run()
        with self.assertRaisesRegex(dymesh.StateError, "the run is finished"):
            run.step()
        with self.assertRaisesRegex(dymesh.StateError, "the run is finished"):
            run.run()
        host = dymesh.load_scenario(BARRIER)
        host.host_step(host.states(), 0.0005)
        with self.assertRaisesRegex(dymesh.StateError, "host-driven"):
            host.step()
        own = dymesh.load_scenario(BARRIER)
        own.step()
        with self.assertRaisesRegex(dymesh.StateError, "stepped by its own integrator"):
            own.host_step(own.states(), 0.0005)

    def test_a_host_run_ends_after_a_host_step(self):
        # a sweep, 2026-11-28: host_finish before any host step ended the run "complete" with 0 steps
        run = dymesh.load_scenario(BARRIER)
        with self.assertRaisesRegex(dymesh.StateError, "no host step taken"):
            run.host_finish(run.states())
        self.assertFalse(run.finished)
        run.host_step(run.states(), 0.0005)
        run.host_finish(run.states())
        self.assertTrue(run.finished)

    def test_ctrl_c_stops_a_run_between_steps(self):
        # a run of a million steps (no stop at separation), interrupted after 0.3 s as Ctrl-C would
        # (until 2026-11-28 the signal was raised only once the run had ended)
        with open(BARRIER, encoding="utf-8") as f:
            spec = json.load(f)
        spec["time"] = {"step": 0.0005, "duration": 500.0, "stop_at_separation": False}
        run = dymesh.scenario(spec, os.path.dirname(BARRIER))
        # a real signal, as a terminal's Ctrl-C is (run() holds the interpreter, so a Python thread
        # could not interrupt it), whose handler raises KeyboardInterrupt
        previous = signal.signal(signal.SIGALRM, signal.default_int_handler)
        try:
            signal.setitimer(signal.ITIMER_REAL, 0.3)
            with self.assertRaises(KeyboardInterrupt):
                run.run()
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
            signal.signal(signal.SIGALRM, previous)
        self.assertFalse(run.finished)
        self.assertEqual(run.status, "interrupted")
        stopped = run.time
        self.assertGreater(stopped, 0.0)
        self.assertLess(stopped, 500.0)
        run.step()  # it goes on from where it stopped
        self.assertAlmostEqual(run.time, stopped + 0.0005, delta=1e-9)

    def test_a_nul_in_a_path_is_refused(self):
        with self.assertRaisesRegex(ValueError, "path: a file name cannot hold a NUL character"):
            dymesh.load_scenario(BARRIER + "\0anything")
        run = dymesh.load_scenario(BARRIER)
        with tempfile.TemporaryDirectory() as out:
            with self.assertRaisesRegex(ValueError, "dir: a file name cannot hold a NUL character"):
                run.write_outputs(os.path.join(out, "a\0b"))
            self.assertEqual(os.listdir(out), [])
            # a folder that cannot take the outputs is named by the parameter, not the command line's --out
            taken = os.path.join(out, "taken")
            open(taken, "w").close()
            with self.assertRaisesRegex(dymesh.InputError, "taken: dir: exists and is not a folder") as refused:
                run.write_outputs(taken)
            self.assertNotIn("--out", str(refused.exception))


class Threads(unittest.TestCase):
    def test_runs_in_two_threads_end_as_one_after_the_other(self):
        # run() lets the interpreter go while it steps: two runs stepping at once in two threads end
        # byte-identical to a run alone (each owns its state; results do not depend on threads)
        alone = dymesh.load_scenario(BARRIER).run().summary_json
        runs = [dymesh.load_scenario(BARRIER) for _ in range(2)]
        threads = [threading.Thread(target=r.run) for r in runs]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        for r in runs:
            self.assertEqual(r.summary_json, alone)

    def test_a_run_stepping_in_another_thread_refuses_other_calls(self):
        # until 2026-11-28 run() held the interpreter, so no other thread could call anything meanwhile;
        # now a call on the run while another thread's run() steps it would see a step in progress
        run = dymesh.load_scenario(BARRIER)
        stepping = threading.Thread(target=run.run)
        stepping.start()
        refused = None
        while stepping.is_alive() and refused is None:
            try:
                run.time  # a read: before run() starts and after it returns, it answers
            except dymesh.StateError as e:
                refused = str(e)
        stepping.join()
        self.assertIn("stepping in another thread", refused or "")
        self.assertTrue(run.finished)
        self.assertEqual(run.summary_json, dymesh.load_scenario(BARRIER).run().summary_json)


class ForceProvider(unittest.TestCase):
    def test_host_loop_gives_the_world_runs_delta_v(self):
        # the host integrates the car in the plane (semi-implicit Euler, as the engine's own host)
        world = dymesh.load_scenario(BARRIER).run()
        run = dymesh.load_scenario(BARRIER)
        car = run.bodies[0]
        states = run.states()
        dt = 0.0005
        for _ in range(world.summary["overall"]["steps"]):
            loads = run.host_step(states, dt)
            moment_z = loads[0, 5]  # body z is earth z for a level car
            states[0, 6:8] += loads[0, 6:8] / car.mass * dt
            states[0, 11] += moment_z / car.inertia[2, 2] * dt
            states[0, 0:2] += states[0, 6:8] * dt
            states[0, 5] += states[0, 11] * dt
        run.host_finish(states)
        self.assertEqual(run.summary["overall"]["steps"], world.summary["overall"]["steps"])
        # the same physics through another host: delta-V within 0.1 % (the engine's host integrates
        # the Euler angles through the DCM; this one adds the yaw rate directly)
        self.assertAlmostEqual(run.bodies[0].delta_v[0], world.bodies[0].delta_v[0],
                               delta=0.001 * abs(world.bodies[0].delta_v[0]))
        self.assertEqual(run.summary["overall"]["status"], "complete")


if __name__ == "__main__":
    unittest.main()
