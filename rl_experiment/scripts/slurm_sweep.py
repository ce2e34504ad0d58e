#!/usr/bin/env python3
"""Run the experiment runner's trials as Slurm job arrays, then merge their folders.

A sweep is a list of runs (one run folder each: an agent's options and a range of trials). Each
run's trials are cut into blocks of --trials-per-task; every block is one array task, the
ordinary runner with --first-trial/--trials and its own part folder
(<run folder>/slurm/parts/trials-FFF-LLL), so trial seeds derive from --seed exactly as in a
local run. One array is submitted per sweep, then a job that waits for it
(--dependency=afterok) and merges the part folders into the run folder, whose per-trial files
are then the same bytes as a local run's (trial-NNN.csv and trials.csv differ only in the
timing columns seconds, steps_per_second and peak_rss_mb).

Rerunning a submission resumes it: finished blocks are not submitted again, a block a killed
task left half-done is finished with the runner's --resume. A failed task can be resubmitted
alone: sbatch --array=K <sweep>/task.sh.

  slurm_sweep.py submit --exe EXPERIMENT --out DIR [--trials N --first-trial F
                 --trials-per-task B --cpus-per-task C --partition P --time T --dry-run]
                 -- <runner options>       the runner's --slurm (experiment --slurm calls it)
  slurm_sweep.py task TASKS.json           one array task ($SLURM_ARRAY_TASK_ID)
  slurm_sweep.py merge DIR                 merge DIR/slurm/parts/* into DIR
"""

import argparse
import csv
import io
import json
import os
import shlex
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON = "/usr/bin/python3" if os.path.exists("/usr/bin/python3") else sys.executable
# Files of a run folder that describe the whole run rather than one trial.
RUN_FILES = ("run.csv", "trials.csv", "seeds.csv")
# Runner options the sweep sets per task (never forwarded from the user's command line).
TASK_OPTIONS = ("out", "trials", "first-trial", "jobs", "resume", "force", "progress")


class SweepError(Exception):
    pass


def finished_trials(folder):
    """Trial numbers in a run folder's trials.csv (a trial's line is written when it ends)."""
    path = os.path.join(folder, "trials.csv")
    if not os.path.exists(path):
        return set()
    with open(path) as f:
        return {int(r["trial"]) for r in csv.DictReader(f) if r.get("trial", "").strip()}


def parts_dir(folder):
    return os.path.join(folder, "slurm", "parts")


def plan_tasks(run_folder, runner_argv, first, trials, per_task, cpus):
    """The array tasks of one run: blocks of per_task trials, each in its own part folder."""
    tasks = []
    for start in range(first, first + trials, per_task):
        count = min(per_task, first + trials - start)
        part = os.path.join(parts_dir(run_folder), "trials-%03d-%03d" % (start, start + count - 1))
        argv = list(runner_argv) + ["--first-trial", str(start), "--trials", str(count),
                                    "--jobs", str(cpus), "--out", part,
                                    "--progress", "off"]
        tasks.append({"folder": run_folder, "part": part, "first": start, "trials": count,
                      "argv": argv})
    return tasks


def task_done(task):
    wanted = set(range(task["first"], task["first"] + task["trials"]))
    return wanted <= finished_trials(task["part"])


def run_task(task):
    """One block: the runner into its part folder, resumed if a killed task left it half-done."""
    if task_done(task):
        print("trials %d-%d already finished in %s" % (task["first"],
              task["first"] + task["trials"] - 1, task["part"]), flush=True)
        return 0
    argv = list(task["argv"])
    if os.path.exists(os.path.join(task["part"], "run.csv")):
        argv.append("--resume")
    elif os.path.isdir(task["part"]):
        shutil.rmtree(task["part"])  # started but wrote nothing the runner could resume
    os.makedirs(os.path.dirname(task["part"]), exist_ok=True)
    print(" ".join(shlex.quote(a) for a in argv), flush=True)
    return subprocess.run(argv).returncode


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.reader(f))


def write_atomic(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w", newline="") as f:
        f.write(text)
    os.replace(tmp, path)


def csv_text(rows):
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerows(rows)
    return out.getvalue()


def merge_rows(parts, name):
    """The header and the rows, sorted by trial, of one per-run table over the part folders."""
    header, rows = None, {}
    for part in parts:
        path = os.path.join(part, name)
        if not os.path.exists(path):
            continue
        table = read_csv(path)
        if not table:
            continue
        if header is None:
            header = table[0]
        elif table[0] != header:
            raise SweepError("%s: its columns differ from the other parts' %s" % (path, name))
        for row in table[1:]:
            if row:
                rows[int(row[0])] = row
    return header, [rows[t] for t in sorted(rows)]


def merge(folder, command_line=None):
    """Merge folder/slurm/parts/* into folder: per-trial files copied, trials.csv and seeds.csv
    joined in trial order, run.csv the first part's with the whole sweep's trials and folder.
    Refuses parts that are not finished or that record a different configuration."""
    pdir = parts_dir(folder)
    if not os.path.isdir(pdir):
        raise SweepError("%s has no Slurm parts (%s)" % (folder, pdir))
    parts = sorted(os.path.join(pdir, p) for p in os.listdir(pdir))
    tasks_file = os.path.join(folder, "slurm", "run-tasks.json")
    expected = json.load(open(tasks_file)) if os.path.exists(tasks_file) else None
    if expected is not None:
        missing = [t["part"] for t in expected if not task_done(t)]
        if missing:
            raise SweepError("unfinished parts in %s: %s" % (folder, ", ".join(missing)))
    fingerprint = None
    for part in parts:
        run = [r for r in read_csv(os.path.join(part, "run.csv"))
               if r and r[0].startswith("option.") and r[0][7:] not in TASK_OPTIONS]
        if fingerprint is None:
            fingerprint = run
        elif run != fingerprint:
            raise SweepError("%s records a different configuration from %s" % (part, parts[0]))
    trials = set()
    for part in parts:
        for name in sorted(os.listdir(part)):
            if name in RUN_FILES or name.endswith(".tmp"):
                continue
            shutil.copyfile(os.path.join(part, name), os.path.join(folder, name + ".tmp"))
            os.replace(os.path.join(folder, name + ".tmp"), os.path.join(folder, name))
        trials |= finished_trials(part)
    for name in ("seeds.csv", "trials.csv"):
        header, rows = merge_rows(parts, name)
        if header is not None:
            write_atomic(os.path.join(folder, name), csv_text([header] + rows))
    first, last = min(trials), max(trials)
    run = read_csv(os.path.join(parts[0], "run.csv"))
    overall = {"option.first-trial": str(first), "option.trials": str(last - first + 1),
               "option.out": folder, "option.jobs": "1"}
    for row in run:
        if row and row[0] in overall:
            row[1] = overall[row[0]]
        elif row and row[0] == "command_line" and command_line:
            row[1] = command_line.replace(",", ";").replace("\n", " ")  # as the runner does
    write_atomic(os.path.join(folder, "run.csv"), csv_text(run))
    return len(trials)


def sbatch(args, dry_run):
    cmd = ["sbatch", "--parsable"] + args
    if dry_run:
        print("would run: " + " ".join(shlex.quote(a) for a in cmd), flush=True)
        return "DRYRUN"
    try:
        res = subprocess.run(cmd, capture_output=True, text=True)
    except FileNotFoundError:
        raise SweepError("sbatch not found: Slurm's client commands are not installed "
                         "(Debian: slurm-client)")
    if res.returncode != 0:
        raise SweepError("sbatch failed (exit %d): %s" % (res.returncode,
                                                          res.stderr.strip() or res.stdout))
    return res.stdout.strip().split(";")[0]


def slurm_args(name, logs, opts, output="%x-%A_%a.out"):
    args = ["--job-name", name, "--output", os.path.join(logs, output)]
    if opts.partition:
        args += ["--partition", opts.partition]
    if opts.time:
        args += ["--time", opts.time]
    return args


def write_tasks(sweep_dir, name, tasks):
    """sweep_dir/tasks.json and task.sh (what an array task runs), and each run folder's own
    list of its tasks (what merge checks)."""
    os.makedirs(os.path.join(sweep_dir, "logs"), exist_ok=True)
    tasks_file = os.path.join(sweep_dir, "tasks.json")
    write_atomic(tasks_file, json.dumps(tasks, indent=1) + "\n")
    for folder in sorted({t["folder"] for t in tasks}):
        os.makedirs(os.path.join(folder, "slurm"), exist_ok=True)
        write_atomic(os.path.join(folder, "slurm", "run-tasks.json"),
                     json.dumps([t for t in tasks if t["folder"] == folder], indent=1) + "\n")
    task_sh = os.path.join(sweep_dir, "task.sh")
    write_atomic(task_sh, "#!/bin/bash\n# One array task of %s: trials of one run folder.\n"
                 "exec %s %s task %s\n" % (name, PYTHON, shlex.quote(os.path.abspath(__file__)),
                                          shlex.quote(tasks_file)))
    os.chmod(task_sh, 0o755)
    return task_sh


def record(sweep_dir, name, job_id):
    with open(os.path.join(sweep_dir, "submitted.csv"), "a") as f:
        f.write("%s,%s\n" % (name, job_id))


def submit_array(sweep_dir, name, tasks, opts, log=print):
    """One array of the unfinished tasks (None if every task is finished)."""
    sweep_dir = os.path.abspath(sweep_dir)
    task_sh = write_tasks(sweep_dir, name, tasks)
    pending = [i for i, t in enumerate(tasks) if not task_done(t)]
    log("%s: %d array tasks, %d finished already" % (name, len(tasks), len(tasks) - len(pending)))
    if not pending:
        return None
    job = sbatch(slurm_args(name, os.path.join(sweep_dir, "logs"), opts) +
                 ["--array", ",".join(str(i) for i in pending),
                  "--cpus-per-task", str(opts.cpus_per_task), task_sh], opts.dry_run)
    record(sweep_dir, name, job)
    return job


def submit_after(sweep_dir, name, command, after, opts):
    """A one-CPU job running `command` once every job in `after` has succeeded."""
    sweep_dir = os.path.abspath(sweep_dir)
    os.makedirs(os.path.join(sweep_dir, "logs"), exist_ok=True)
    script = os.path.join(sweep_dir, name + ".sh")
    write_atomic(script, "#!/bin/bash\n# After every task: merge and report.\nset -e\n%s\n"
                 % command)
    os.chmod(script, 0o755)
    args = slurm_args(name, os.path.join(sweep_dir, "logs"), opts, "%x-%j.out")
    after = [a for a in after if a]
    if after:
        args += ["--dependency", "afterok:" + ":".join(after)]
    job = sbatch(args + [script], opts.dry_run)
    record(sweep_dir, name, job)
    return job


def follow_hint(sweep_dir, ids):
    ids = ",".join(i for i in ids if i)
    return ("follow with: squeue -j %s   (finished: sacct -j %s; on tools/slurm_local.sh's "
            "cluster sacct -c)\nlogs: %s/logs/; resubmit one failed task K alone: "
            "sbatch --array=K %s/task.sh" % (ids, ids, sweep_dir, sweep_dir))


SLURM_VALUE_ARGUMENTS = ("--partition", "--time", "--cpus-per-task", "--trials-per-task")
SLURM_FLAG_ARGUMENTS = ("--slurm", "--slurm-dry-run", "--collect")


def add_slurm_arguments(ap):
    """The Slurm options of a reproduce script (the runner's --slurm has the same names)."""
    ap.add_argument("--slurm", action="store_true",
                    help="submit to Slurm: one job array per experiment (a task per agent and "
                         "block of trials), then a job that merges and reports; rerun to resume")
    ap.add_argument("--partition", default="", help="with --slurm: the partition")
    ap.add_argument("--time", default="", help="with --slurm: each task's time limit")
    ap.add_argument("--cpus-per-task", type=int, default=1,
                    help="with --slurm: CPUs per array task (it runs that many trials at once)")
    ap.add_argument("--trials-per-task", type=int, default=0,
                    help="with --slurm: trials per array task (default: --cpus-per-task)")
    ap.add_argument("--slurm-dry-run", dest="dry_run", action="store_true",
                    help="with --slurm: write the scripts and print the sbatch commands only")
    ap.add_argument("--collect", action="store_true",
                    help="(the report job) merge the Slurm tasks' folders, then report")


def strip_slurm_arguments(argv):
    """argv without the Slurm options (both --name value and --name=value forms)."""
    out, skip = [], False
    for a in argv:
        if skip:
            skip = False
            continue
        name = a.split("=", 1)[0]
        if name in SLURM_FLAG_ARGUMENTS or (name in SLURM_VALUE_ARGUMENTS and "=" in a):
            continue
        if name in SLURM_VALUE_ARGUMENTS:
            skip = True
            continue
        out.append(a)
    return out


def collect_command(exe, script, argv, out):
    """The report job's shell line: `script` rerun with argv minus the Slurm options, plus
    --collect, on the same runner."""
    args = strip_slurm_arguments(argv) + ["--collect", "--out", out]
    return "RL_EXPERIMENT=%s %s %s %s" % (shlex.quote(os.path.abspath(exe)), PYTHON,
                                         shlex.quote(os.path.abspath(script)),
                                         " ".join(shlex.quote(a) for a in args))


def cmd_submit(argv):
    ap = argparse.ArgumentParser(prog="slurm_sweep.py submit")
    ap.add_argument("--exe", required=True, help="the experiment runner")
    ap.add_argument("--out", required=True, help="the run folder the merge job fills")
    ap.add_argument("--first-trial", type=int, default=0)
    ap.add_argument("--trials", type=int, default=1)
    ap.add_argument("--trials-per-task", type=int, default=0,
                    help="trials per array task (default: --cpus-per-task)")
    ap.add_argument("--cpus-per-task", type=int, default=1)
    ap.add_argument("--partition", default="")
    ap.add_argument("--time", default="")
    ap.add_argument("--command-line", default="", help="recorded in the merged run.csv")
    ap.add_argument("--dry-run", action="store_true", help="write the scripts, print sbatch")
    ap.add_argument("runner", nargs=argparse.REMAINDER, help="-- then the runner's options")
    opts = ap.parse_args(argv)
    runner = opts.runner[1:] if opts.runner[:1] == ["--"] else opts.runner
    per_task = opts.trials_per_task or opts.cpus_per_task
    out = os.path.abspath(opts.out)
    os.makedirs(out, exist_ok=True)
    tasks = plan_tasks(out, [os.path.abspath(opts.exe)] + runner, opts.first_trial, opts.trials,
                       per_task, opts.cpus_per_task)
    sweep = os.path.join(out, "slurm")
    merge_cmd = "%s %s merge %s --command-line %s" % (
        PYTHON, shlex.quote(os.path.abspath(__file__)), shlex.quote(out),
        shlex.quote(opts.command_line or "slurm_sweep.py"))
    name = "rl-" + os.path.basename(out)
    array_id = submit_array(sweep, name, tasks, opts)
    merge_id = submit_after(sweep, name + "-merge", merge_cmd, [array_id], opts)
    print("submitted: array job %s (%d tasks), merge job %s" % (array_id or "none", len(tasks),
                                                                merge_id))
    print(follow_hint(sweep, [array_id, merge_id]))
    return 0


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv else 2
    try:
        if argv[0] == "submit":
            return cmd_submit(argv[1:])
        if argv[0] == "task":
            tasks = json.load(open(argv[1]))
            index = int(os.environ.get("SLURM_ARRAY_TASK_ID", argv[2] if len(argv) > 2 else -1))
            if not 0 <= index < len(tasks):
                raise SweepError("no task %d in %s (%d tasks)" % (index, argv[1], len(tasks)))
            return run_task(tasks[index])
        if argv[0] == "merge":
            ap = argparse.ArgumentParser(prog="slurm_sweep.py merge")
            ap.add_argument("folder")
            ap.add_argument("--command-line", default="")
            a = ap.parse_args(argv[1:])
            n = merge(os.path.abspath(a.folder), a.command_line)
            print("merged %d trials into %s" % (n, a.folder))
            return 0
    except SweepError as e:
        print("slurm_sweep.py: %s" % e, file=sys.stderr)
        return 1
    print("slurm_sweep.py: unknown command %r; valid: submit, task, merge" % argv[0],
          file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main())
