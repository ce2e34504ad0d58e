#!/usr/bin/env python3
"""The reproduction tables' statistics: stats.py's Welch t-test against hand-computed values and
closed forms of the t distribution, and plot_results.py's p-value columns on fabricated run
folders.

Run directly (/usr/bin/python3 rl_experiment/test/test_stats.py [--xunit FILE]) or through
`./rl test`, which registers it with catkin_run_tests_target and reads the JUnit FILE.
"""
import contextlib
import csv
import io
import math
import os
import shutil
import sys
import tempfile
import time
import unittest
from xml.sax.saxutils import escape, quoteattr

SCRIPTS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts")
sys.path.insert(0, os.path.abspath(SCRIPTS))
import stats  # noqa: E402
import plot_results  # noqa: E402
import plot_trials  # noqa: E402
import trials_table  # noqa: E402
import diagnose_exploration  # noqa: E402


class IncompleteBeta(unittest.TestCase):
    def test_closed_forms(self):
        for x in (0.01, 0.2, 0.5, 0.77, 0.99):
            for a in (0.5, 1.0, 2.5, 7.0):
                self.assertAlmostEqual(stats.betai(a, 1.0, x), x ** a, places=12)
                self.assertAlmostEqual(stats.betai(1.0, a, x), 1.0 - (1.0 - x) ** a, places=12)
                # I_x(a, b) = 1 - I_{1-x}(b, a)
                self.assertAlmostEqual(stats.betai(a, 3.5, x), 1.0 - stats.betai(3.5, a, 1 - x),
                                       places=12)

    def test_ends_and_invalid_arguments(self):
        self.assertEqual(stats.betai(2.0, 3.0, 0.0), 0.0)
        self.assertEqual(stats.betai(2.0, 3.0, 1.0), 1.0)
        for a, b, x in ((0.0, 1.0, 0.5), (1.0, -1.0, 0.5), (1.0, 1.0, 1.5)):
            with self.assertRaises(ValueError):
                stats.betai(a, b, x)


class StudentT(unittest.TestCase):
    def test_table_quantile(self):
        # t_{0.975, 10} = 2.228 (every t table).
        self.assertAlmostEqual(stats.student_t_two_sided_p(2.228, 10), 0.05, places=4)
        self.assertAlmostEqual(stats.student_t_two_sided_p(12.706, 1), 0.05, places=4)
        self.assertAlmostEqual(stats.student_t_cdf(2.228, 10), 0.975, places=4)
        self.assertAlmostEqual(stats.student_t_cdf(-2.228, 10), 0.025, places=4)

    def test_closed_forms(self):
        for t in (0.3, 1.0, 2.0, 5.0, 40.0):
            # df = 1 (Cauchy): P(|T| >= t) = 1 - 2 atan(t) / pi.
            self.assertAlmostEqual(stats.student_t_two_sided_p(t, 1),
                                   1 - 2 * math.atan(t) / math.pi, places=12)
            # df = 2: P(|T| >= t) = 1 - t / sqrt(2 + t^2).
            self.assertAlmostEqual(stats.student_t_two_sided_p(t, 2), 1 - t / math.sqrt(2 + t * t),
                                   places=12)
            # df = 4: P(|T| >= t) = 1 - (3/2) s (1 - s^2/3) with s = t / sqrt(4 + t^2).
            s = t / math.sqrt(4 + t * t)
            self.assertAlmostEqual(stats.student_t_two_sided_p(t, 4), 1 - 1.5 * s * (1 - s * s / 3),
                                   places=12)

    def test_limits(self):
        self.assertEqual(stats.student_t_two_sided_p(0.0, 7), 1.0)
        self.assertEqual(stats.student_t_two_sided_p(float("inf"), 7), 0.0)
        # Many degrees of freedom: the normal's 1.959964.
        self.assertAlmostEqual(stats.student_t_two_sided_p(1.959964, 1e6), 0.05, places=5)
        with self.assertRaises(ValueError):
            stats.student_t_two_sided_p(1.0, 0)


class WelchTTest(unittest.TestCase):
    def test_hand_computed(self):
        # m = 3, 6; s^2 = 2.5, 10; se^2 = 0.5 + 2 = 2.5; t = -3 / sqrt(2.5);
        # df = 2.5^2 / (0.5^2/4 + 2^2/4) = 6.25 / 1.0625 = 5.88235 (R: t.test gives p = 0.1075).
        t, df, p = stats.welch_t_test([1, 2, 3, 4, 5], [2, 4, 6, 8, 10])
        self.assertAlmostEqual(t, -3 / math.sqrt(2.5), places=12)
        self.assertAlmostEqual(t, -1.8974, places=4)
        self.assertAlmostEqual(df, 6.25 / 1.0625, places=12)
        self.assertAlmostEqual(df, 5.882, places=3)
        self.assertAlmostEqual(p, 0.1075, places=4)

    def test_equal_sizes_and_variances_is_students_test(self):
        # s^2 = 1 each, n = 3: t = -3 / sqrt(2/3), df = 2n - 2 = 4.
        t, df, p = stats.welch_t_test([1, 2, 3], [4, 5, 6])
        self.assertAlmostEqual(t, -3 / math.sqrt(2 / 3), places=12)
        self.assertAlmostEqual(df, 4.0, places=12)
        self.assertAlmostEqual(p, stats.student_t_two_sided_p(t, 4), places=15)
        self.assertAlmostEqual(p, 0.02131, places=5)

    def test_identical_groups(self):
        t, df, p = stats.welch_t_test([3.0, 1.0, 2.0, 5.0], [3.0, 1.0, 2.0, 5.0])
        self.assertEqual(t, 0.0)
        self.assertEqual(p, 1.0)

    def test_separated_groups(self):
        t, _, p = stats.welch_t_test([10.0, 10.1, 9.9, 10.05, 9.95], [1.0, 1.1, 0.9, 1.05, 0.95])
        self.assertGreater(t, 0)
        self.assertLess(p, 1e-4)

    def test_symmetric(self):
        a, b = [0.2, 0.5, 0.1, 0.9], [0.6, 0.8, 0.7]
        t1, df1, p1 = stats.welch_t_test(a, b)
        t2, df2, p2 = stats.welch_t_test(b, a)
        self.assertAlmostEqual(t1, -t2, places=12)
        self.assertAlmostEqual(df1, df2, places=12)
        self.assertAlmostEqual(p1, p2, places=12)

    def test_one_constant_group(self):
        # Only b varies: se^2 = s2^2/n2 and df = n2 - 1.
        t, df, p = stats.welch_t_test([0.0, 0.0, 0.0], [1.0, 2.0, 3.0])
        self.assertAlmostEqual(t, -2 / math.sqrt(1 / 3), places=12)
        self.assertAlmostEqual(df, 2.0, places=12)
        self.assertAlmostEqual(p, 1 - abs(t) / math.sqrt(2 + t * t), places=12)

    def test_undefined_cases_are_nan(self):
        for a, b in (([1.0], [1.0, 2.0]), ([1.0, 2.0], []), ([4.0, 4.0], [5.0, 5.0, 5.0]),
                     ([float("nan"), 1.0], [1.0, 2.0])):
            self.assertTrue(all(math.isnan(v) for v in stats.welch_t_test(a, b)), (a, b))

    def test_nan_values_are_ignored(self):
        self.assertEqual(stats.welch_t_test([1, 2, float("nan"), 3, 4, 5], [2, 4, 6, 8, 10]),
                         stats.welch_t_test([1, 2, 3, 4, 5], [2, 4, 6, 8, 10]))

    def test_format(self):
        self.assertEqual(stats.format_p(float("nan")), "n/a")
        self.assertEqual(stats.format_p(None), "n/a")
        self.assertEqual(stats.format_p(0.0004), "< 0.001")
        self.assertEqual(stats.format_p(0.1075312), "0.108")
        self.assertEqual(stats.format_p(1.0), "1.000")


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)


STEPS = ["trial", "step", "phase", "episode", "action", "reward", "reward_seen", "variance",
         "novelty", "other", "target", "terminal"]


def fake_run(folder, label, rewards, distances, speeds):
    """A run folder as the experiment runner writes it: one trial per value; trial i earns
    rewards[i] in its task phase, ends at variational distance distances[i] and ran at
    speeds[i] steps/s."""
    os.makedirs(folder)
    write_csv(os.path.join(folder, "run.csv"), ["name", "value"], [["label", label]])
    for i, (reward, distance, speed) in enumerate(zip(rewards, distances, speeds)):
        steps = [[i, s, "explore" if s < 2 else "task", 0, 5 if s % 2 else 0,
                  reward if s == 3 else 0, 0, 0, 0, 0, "key" if s % 2 else "", 0]
                 for s in range(4)]
        write_csv(os.path.join(folder, "steps-%03d.csv" % i), STEPS, steps)
        write_csv(os.path.join(folder, "accuracy-%03d.csv" % i),
                  ["trial", "step", "phase", "variational_distance", "samples"],
                  [[i, 0, "explore", 0.9, 10], [i, 2, "explore", distance, 10]])
        write_csv(os.path.join(folder, "trial-%03d.csv" % i),
                  ["trial", "label", "agent", "total_reward", "steps_per_second"],
                  [[i, label, "texplore", reward, speed]])


def table_rows(text):
    """{agent: [cells]} of the markdown table in `text`."""
    rows = {}
    for line in text.splitlines():
        if line.startswith("| ") and not line.startswith("| agent"):
            cells = [c.strip() for c in line.strip().strip("|").split("|")]
            rows[cells[0]] = cells[1:]
    return rows


class WriteTable(unittest.TestCase):
    VANIR = ([10, 12, 14], [0.2, 0.25, 0.3], [100, 110, 120])
    OTHER = ([1, 2, 3], [0.5, 0.6, 0.55], [300, 310, 320])

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="rl_test_stats_")
        # The reference is not the first folder: texplore-vanir is found by its label.
        fake_run(os.path.join(self.tmp, "other"), "other", *self.OTHER)
        fake_run(os.path.join(self.tmp, "vanir"), "texplore-vanir", *self.VANIR)
        fake_run(os.path.join(self.tmp, "single"), "single", [5], [0.4], [200])
        self.out = os.path.join(self.tmp, "figs")

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def runs(self):
        runs = []
        for name in ("other", "vanir", "single"):
            folder = os.path.join(self.tmp, name)
            run = plot_results.Run(plot_results.label_of(folder))
            run.add_folder(folder)
            runs.append(run)
        return runs

    def test_reference_row_and_p_values(self):
        os.makedirs(self.out)
        text = plot_results.write_table(self.runs(), self.out, "test")
        with open(os.path.join(self.out, "results.md")) as f:
            self.assertEqual(f.read(), text)
        rows = table_rows(text)
        # agent | trials | reward | p | distance | p | PRESS fraction | p | steps/s | p
        self.assertEqual(rows["texplore-vanir"][0], "3")
        self.assertEqual(rows["texplore-vanir"][2::2], ["ref"] * 4)
        other = rows["other"]
        self.assertEqual(other[1], "2.0 \u00b1 2.5")
        for i, values in ((2, 0), (4, 1), (8, 2)):
            expected = stats.welch_t_test(self.OTHER[values], self.VANIR[values])[2]
            self.assertEqual(other[i], stats.format_p(expected), (i, text))
        self.assertEqual(other[2], stats.format_p(stats.welch_t_test([1, 2, 3], [10, 12, 14])[2]))
        self.assertNotEqual(other[2], "n/a")
        # Every trial presses on the key only: both fractions are 1 with zero variance.
        self.assertEqual(other[6], "n/a")
        # One trial: no test.
        self.assertEqual(rows["single"][2::2], ["n/a"] * 4)
        self.assertIn("two-sided Welch t-test", text)
        self.assertIn("against texplore-vanir", text)
        self.assertIn("per-trial values", text)

    def test_explicit_reference(self):
        os.makedirs(self.out)
        rows = table_rows(plot_results.write_table(self.runs(), self.out, "", reference="other"))
        self.assertEqual(rows["other"][2::2], ["ref"] * 4)
        # The test is symmetric: texplore-vanir against other has the p of other against it.
        self.assertEqual(rows["texplore-vanir"][2],
                         stats.format_p(stats.welch_t_test(self.VANIR[0], self.OTHER[0])[2]))

    def test_first_run_is_the_default_without_texplore_vanir(self):
        os.makedirs(self.out)
        runs = [r for r in self.runs() if r.label != "texplore-vanir"]
        rows = table_rows(plot_results.write_table(runs, self.out, ""))
        self.assertEqual(rows["other"][2::2], ["ref"] * 4)

    def test_script_with_reference_option(self):
        folders = [os.path.join(self.tmp, n) for n in ("other", "vanir")]
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            self.assertEqual(plot_results.main(["--out", self.out, "--reference", "other"]
                                               + folders), 0)
        self.assertIn("against other", out.getvalue())
        with open(os.path.join(self.out, "results.md")) as f:
            self.assertEqual(table_rows(f.read())["other"][2::2], ["ref"] * 4)

    def test_unknown_reference_lists_the_labels(self):
        err = io.StringIO()
        with contextlib.redirect_stderr(err), self.assertRaises(SystemExit) as e:
            plot_results.main(["--out", self.out, "--reference", "nope",
                               os.path.join(self.tmp, "other"), os.path.join(self.tmp, "vanir")])
        self.assertNotEqual(e.exception.code, 0)
        self.assertIn("nope", err.getvalue())
        self.assertIn("other, texplore-vanir", err.getvalue())


class FloorAdjusted(unittest.TestCase):
    """diagnose_exploration.py's comparison at equal steps with the key on the floor."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp()

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def folder(self, name, trials):
        path = os.path.join(self.tmp, name)
        os.makedirs(path)
        for i, (floor, dist) in enumerate(trials):
            with open(os.path.join(path, "trial-%03d.csv" % i), "w", newline="") as f:
                w = csv.writer(f)
                w.writerow(["trial", "explore_key_on_floor", "final_accuracy"])
                w.writerow([i, floor, dist])
        return path

    def test_a_shift_at_equal_floor_time_is_found_and_a_floor_effect_is_not_one(self):
        floors = [20, 50, 100, 200, 400, 800]
        law = [0.9 - 0.05 * math.log1p(f) for f in floors]
        noise = [0.004, -0.003, 0.002, -0.004, 0.003, -0.002]
        ref = self.folder("ref", [(f, d + e) for f, d, e in zip(floors, law, noise)])
        # Same law, 0.03 lower: a real difference at equal floor time.
        lower = self.folder("lower", [(f, d - 0.03 - e) for f, d, e in zip(floors, law, noise)])
        diff, se, p, r2 = diagnose_exploration.floor_adjusted(lower, ref)
        self.assertAlmostEqual(diff, -0.03, delta=0.005)
        self.assertLess(p, 0.001)
        self.assertGreater(r2, 0.9)
        # Same law, only more floor time: a lower raw mean, no difference once adjusted.
        more = self.folder("more", [(f * 4, 0.9 - 0.05 * math.log1p(f * 4) - e)
                                    for f, e in zip(floors, noise)])
        diff, se, p, _ = diagnose_exploration.floor_adjusted(more, ref)
        self.assertLess(abs(diff), 0.01)
        self.assertGreater(p, 0.05)

    def test_too_few_trials_give_no_comparison(self):
        a = self.folder("a", [(10, 0.5), (20, 0.4)])
        b = self.folder("b", [(10, 0.5), (30, 0.4)])
        self.assertIsNone(diagnose_exploration.floor_adjusted(a, b))


class PlotTrials(unittest.TestCase):
    """plot_trials.py on a fabricated per-trial CSV: sums, ratios, empty cells, p, errors."""

    HEADER = ["agent", "trial", "distance", "hits", "misses"]
    ROWS = [["texplore-vanir", 0, 0.2, 3, 1], ["texplore-vanir", 1, 0.3, 1, 1],
            ["texplore-vanir", 2, 0.25, 2, 2], ["other", 0, 0.5, 0, 4], ["other", 1, "", 1, 3],
            ["other", 2, 0.6, 0, 0]]

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="rl_test_plot_trials_")
        self.csv = os.path.join(self.tmp, "trials.csv")
        write_csv(self.csv, self.HEADER, self.ROWS)
        self.out = os.path.join(self.tmp, "figs")

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def run_main(self, *args):
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = plot_trials.main([self.csv, "--out", self.out] + list(args))
        return code, out.getvalue(), err.getvalue()

    def test_figures_and_table(self):
        code, out, _ = self.run_main("--agents", "other,texplore-vanir", "--column",
                                     "distance=distance", "--column", "share=hits/hits+misses")
        self.assertEqual(code, 0)
        for name in ("distance.png", "distance.pdf", "share.png", "share.pdf", "results.md"):
            self.assertTrue(os.path.getsize(os.path.join(self.out, name)) > 0, name)
        rows = table_rows(out)
        self.assertEqual(list(rows), ["other", "texplore-vanir"])  # --agents' order
        # distance: the empty cell is left out (2 trials); vanir is the reference by name.
        self.assertEqual(rows["other"][1], "2")
        self.assertEqual(rows["texplore-vanir"][2], "ref")
        p = stats.welch_t_test([0.5, 0.6], [0.2, 0.3, 0.25])[2]
        self.assertEqual(rows["other"][2], stats.format_p(p))
        # share: 3/4, 1/2, 2/4 for vanir; other's 0/0 trial is missing, not zero.
        mean, half, n = plot_results.ci95([0.75, 0.5, 0.5])
        self.assertEqual(rows["texplore-vanir"][3], "%.3f ± %.3f" % (mean, half))
        self.assertEqual(rows["other"][4], "2")
        with open(os.path.join(self.out, "results.md")) as f:
            self.assertIn(rows["other"][3], f.read())

    def test_bad_input_is_refused_with_what_is_valid(self):
        code, _, err = self.run_main("--column", "d=nosuch")
        self.assertEqual(code, 2)
        self.assertIn("no column 'nosuch'", err)
        self.assertIn("distance", err)  # lists the CSV's columns
        code, _, err = self.run_main("--column", "d=distance", "--agents", "ghost")
        self.assertEqual(code, 2)
        self.assertIn("texplore-vanir", err)
        code, _, err = self.run_main("--column", "distance")
        self.assertEqual(code, 2)
        self.assertIn("LABEL=SPEC", err)
        self.assertFalse(os.path.exists(self.out))  # nothing written on a refused call


class TrialsTable(unittest.TestCase):
    """trials_table.py: every trial's summary and its distance at a step, from run folders."""

    def setUp(self):
        self.tmp = tempfile.mkdtemp(prefix="rl_test_trials_table_")
        fake_run(os.path.join(self.tmp, "a"), "texplore-vanir", [10, 12], [0.2, 0.3], [100, 110])
        fake_run(os.path.join(self.tmp, "b"), "other", [1], [0.5], [300])
        os.makedirs(os.path.join(self.tmp, "empty"))
        self.out = os.path.join(self.tmp, "per-trial.csv")

    def tearDown(self):
        shutil.rmtree(self.tmp)

    def call(self, *args):
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            return trials_table.main(list(args))

    def test_rows_and_distances(self):
        code = self.call(os.path.join(self.tmp, "a"), os.path.join(self.tmp, "b"), "--out",
                         self.out, "--at-step", "2", "--at-step", "7")
        self.assertEqual(code, 0)
        with open(self.out, newline="") as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([(r["agent"], r["trial"]) for r in rows],
                         [("texplore-vanir", "0"), ("texplore-vanir", "1"), ("other", "0")])
        self.assertEqual([r["total_reward"] for r in rows], ["10", "12", "1"])
        self.assertEqual({r["agent_type"] for r in rows}, {"texplore"})  # the label is `agent`
        self.assertEqual([float(r["distance_step2"]) for r in rows], [0.2, 0.3, 0.5])
        self.assertEqual([r["distance_step7"] for r in rows], ["", "", ""])  # never measured
        self.assertFalse(os.path.exists(self.out + ".tmp"))
        # plot_trials.py draws from the table: the reference's mean distance at step 2.
        out = io.StringIO()
        with contextlib.redirect_stdout(out):
            code = plot_trials.main([self.out, "--out", os.path.join(self.tmp, "figs"),
                                     "--column", "d=distance_step2"])
        self.assertEqual(code, 0)
        mean, half, _ = plot_results.ci95([0.2, 0.3])
        self.assertEqual(table_rows(out.getvalue())["texplore-vanir"][0],
                         "%.3f ± %.3f" % (mean, half))

    def test_a_folder_without_trials_is_an_error_and_keeps_the_old_table(self):
        with open(self.out, "w") as f:
            f.write("kept\n")
        code = self.call(os.path.join(self.tmp, "a"), os.path.join(self.tmp, "empty"), "--out",
                         self.out)
        self.assertEqual(code, 2)
        with open(self.out) as f:
            self.assertEqual(f.read(), "kept\n")


class _Recorder(unittest.TextTestResult):
    """Keeps every outcome with its time, for the JUnit file."""

    def __init__(self, *args, **kwargs):
        super().__init__(*args, **kwargs)
        self.cases = []  # (test, kind, text, seconds)

    def startTest(self, test):
        self._t0 = time.time()
        super().startTest(test)

    def _record(self, test, kind, text=""):
        self.cases.append((test, kind, text, time.time() - self._t0))

    def addSuccess(self, test):
        super().addSuccess(test)
        self._record(test, "ok")

    def addFailure(self, test, err):
        super().addFailure(test, err)
        self._record(test, "failure", self.failures[-1][1])

    def addError(self, test, err):
        super().addError(test, err)
        self._record(test, "error", self.errors[-1][1])

    def addSkip(self, test, reason):
        super().addSkip(test, reason)
        self._record(test, "skipped", reason)


def write_xunit(path, result, suite="rl_experiment.test_stats"):
    failures = sum(1 for c in result.cases if c[1] == "failure")
    errors = sum(1 for c in result.cases if c[1] == "error")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as out:
        out.write('<?xml version="1.0" encoding="UTF-8"?>\n')
        out.write('<testsuite name=%s tests="%d" failures="%d" errors="%d">\n'
                  % (quoteattr(suite), len(result.cases), failures, errors))
        for test, kind, text, seconds in result.cases:
            cls, name = test.id().rsplit(".", 1)
            out.write('  <testcase classname=%s name=%s time="%.3f">'
                      % (quoteattr(cls.rsplit(".", 1)[-1]), quoteattr(name), seconds))
            if kind in ("failure", "error"):
                first = text.strip().splitlines()[-1] if text.strip() else kind
                out.write('<%s message=%s>%s</%s>' % (kind, quoteattr(first), escape(text), kind))
            elif kind == "skipped":
                out.write('<skipped message=%s/>' % quoteattr(text))
            out.write("</testcase>\n")
        out.write("</testsuite>\n")


def main(argv):
    xunit = None
    if "--xunit" in argv:
        i = argv.index("--xunit")
        xunit = argv[i + 1]
        argv = argv[:i] + argv[i + 2:]
    if xunit is None:
        return unittest.main(argv=[sys.argv[0]] + argv)
    suite = unittest.defaultTestLoader.loadTestsFromModule(sys.modules[__name__])
    result = unittest.TextTestRunner(resultclass=_Recorder, verbosity=2).run(suite)
    write_xunit(xunit, result)
    return 0 if result.wasSuccessful() else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
