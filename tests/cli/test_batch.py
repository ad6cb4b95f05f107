"""`compatmesh batch`: one triangulate job per line of a list, run on
several processes. Each job writes exactly what `triangulate` writes for
the same inputs and options; a failing job is recorded and the others still
run; a malformed list starts nothing; SIGINT leaves only complete folders."""
import json
import os
import re
import signal
import subprocess

import pytest

from polygons import KITE, SQUARE, leftovers, snapshot, star, twisted_pair, write_xy

MESH_SUFFIXES = (".off", ".obj", ".ply")


def strict_json(path):
    def reject(constant):
        raise ValueError(f"{path}: non-finite number {constant} in JSON")
    with open(path) as f:
        return json.load(f, parse_constant=reject)


@pytest.fixture
def pairs(tmp_path):
    """A list in lists/ naming polygons in data/ (relative to the list) and
    one by absolute path: four jobs, one of them of three polygons."""
    data = tmp_path / "data"
    data.mkdir()
    write_xy(data / "square.xy", SQUARE)
    write_xy(data / "kite.xy", KITE)
    for seed in (1, 2, 3):
        write_xy(data / f"star{seed}.xy", star(14, seed))
    twisted_a, twisted_b = twisted_pair()
    write_xy(data / "ta.xy", twisted_a)
    write_xy(data / "tb.xy", twisted_b)
    lists = tmp_path / "lists"
    lists.mkdir()
    listing = lists / "jobs.txt"
    listing.write_text("# four jobs\n"
                       "../data/square.xy ../data/kite.xy\n"
                       "\n"
                       f"three: ../data/star1.xy ../data/star2.xy {data / 'star3.xy'}  # k = 3\n"
                       "   ../data/ta.xy\t../data/tb.xy\n"
                       "stars: ../data/star1.xy ../data/star3.xy\n")
    expected = {  # folder -> inputs as the batch resolves them
        "2-square": ["data/square.xy", "data/kite.xy"],
        "three": ["data/star1.xy", "data/star2.xy", "data/star3.xy"],
        "5-ta": ["data/ta.xy", "data/tb.xy"],
        "stars": ["data/star1.xy", "data/star3.xy"],
    }
    return listing, expected


@pytest.mark.parametrize("options", [["--format", "obj", "--min-angle", "22"], ["--no-preview"],
                                     ["--no-preview", "--time-limit", "1e-6"]])
def test_batch_writes_what_triangulate_writes(cm, tmp_path, pairs, options):
    listing, expected = pairs
    result = cm("batch", listing, "--out-dir", tmp_path / "out", "--jobs", "2", *options)
    assert result.returncode == 0, result.stderr
    lines = result.stderr.splitlines()
    assert len(lines) == len(expected)
    for i, line in enumerate(lines, 1):
        assert re.fullmatch(rf"compatmesh: batch: \[{i}/4\] (\S+) ok: \d+ Steiner, smallest angles "
                            r"[\d.]+(, [\d.]+)* deg, [\d.]+ s CPU", line), line
    assert sorted(re.search(r"\] (\S+) ok", line).group(1) for line in lines) == sorted(expected)
    assert result.stdout == (f"wrote {tmp_path / 'out' / 'batch.json'}: 4 jobs, 4 ok, 0 bad input, "
                             "0 internal failures\n")
    assert sorted(os.listdir(tmp_path / "out")) == sorted([*expected, "batch.json"])
    (tmp_path / "alone").mkdir()
    for folder, inputs in expected.items():
        alone = tmp_path / "alone" / folder
        single = cm("triangulate", *(tmp_path / p for p in inputs), "--out-dir", alone, *options)
        assert single.returncode == 0, single.stderr
        written = sorted(os.listdir(tmp_path / "out" / folder))
        assert written == sorted(os.listdir(alone))
        assert ("preview.svg" in written) == ("--no-preview" not in options)
        meshes = [name for name in written if name.endswith(MESH_SUFFIXES)]
        assert len(meshes) == len(inputs)
        for name in meshes:
            assert (tmp_path / "out" / folder / name).read_bytes() == (alone / name).read_bytes(), \
                f"{folder}/{name}"
        batch_report = strict_json(tmp_path / "out" / folder / "report.json")
        single_report = strict_json(alone / "report.json")
        for key in ("n", "k", "steiner", "triangles", "remesh_aim_deg", "time_limit_reached"):
            assert batch_report[key] == single_report[key], key
        # a limit spent before remeshing starts stops every job there
        assert batch_report["time_limit_reached"] == ("--time-limit" in options)


def test_batch_json_reads_back(cm, tmp_path, pairs):
    listing, expected = pairs
    result = cm("batch", listing, "-o", tmp_path / "out", "-j", "3", "--quiet")
    assert result.returncode == 0, result.stderr
    assert result.stdout == "" and result.stderr == ""
    report = strict_json(tmp_path / "out" / "batch.json")
    assert report["list"] == str(listing)
    assert report["out_dir"] == str(tmp_path / "out")
    assert report["workers"] == 3
    assert (report["jobs_total"], report["ok"], report["bad_input"], report["internal_failure"]) == (4, 4, 0, 0)
    assert report["exit_code"] == 0
    assert [job["line"] for job in report["jobs"]] == [2, 4, 5, 6]
    assert [job["name"] for job in report["jobs"]] == list(expected)
    total = 0
    for job, (folder, inputs) in zip(report["jobs"], expected.items()):
        assert job["out_dir"] == str(tmp_path / "out" / folder)
        assert [os.path.realpath(p) for p in job["inputs"]] == \
            [os.path.realpath(tmp_path / p) for p in inputs]
        assert job["inputs"][2:] == [str(tmp_path / "data" / "star3.xy")] * (folder == "three")
        assert (job["status"], job["exit_code"], job["message"]) == ("ok", 0, None)
        mesh_report = strict_json(tmp_path / "out" / folder / "report.json")
        assert job["steiner"] == mesh_report["steiner"]
        # The same doubles as the job's own report, to the last bit.
        assert job["min_angle_deg"] == [mesh["min_angle_deg"] for mesh in mesh_report["meshes"]]
        assert job["cpu_seconds"] > 0
        total += job["cpu_seconds"]
    assert report["cpu_seconds"] == pytest.approx(total, rel=1e-12)
    assert report["wall_seconds"] > 0


def test_failing_jobs_are_recorded_and_the_others_written(cm, tmp_path, pairs):
    listing, expected = pairs
    data = tmp_path / "data"
    (data / "broken.xy").write_text("0 0\n1 0\n1 zero\n0 1\n")
    with open(listing, "a") as f:
        f.write("../data/kite.xy ../data/broken.xy\n")  # line 7
    single = cm("triangulate", data / "kite.xy", data / "broken.xy", "--out-dir", tmp_path / "alone")
    assert single.returncode == 2
    out = tmp_path / "out"
    result = cm("batch", listing, "--out-dir", out, "--jobs", "2")
    assert result.returncode == 2, result.stderr
    failed = [line for line in result.stderr.splitlines() if " ok: " not in line]
    message = single.stderr.strip().removeprefix("compatmesh: ").replace(
        str(data), os.path.join(os.path.dirname(str(listing)), "../data"))
    assert len(failed) == 1
    assert re.fullmatch(r"compatmesh: batch: \[[1-5]/5\] 7-kite bad input: (.*)", failed[0]).group(1) == message
    assert sorted(os.listdir(out)) == sorted([*expected, "batch.json"])
    report = strict_json(out / "batch.json")
    assert (report["ok"], report["bad_input"], report["internal_failure"], report["exit_code"]) == (4, 1, 0, 2)
    bad = report["jobs"][-1]
    assert (bad["line"], bad["name"], bad["status"], bad["exit_code"]) == (7, "7-kite", "bad_input", 2)
    assert bad["message"] == message
    assert bad["steiner"] is None and bad["min_angle_deg"] is None

    # A job whose folder holds a directory where its report.json goes cannot
    # commit: an internal failure, which makes the batch's status 1, and the
    # folder is left as it was.
    (out / "stars").mkdir(exist_ok=True)
    for name in os.listdir(out / "stars"):
        os.remove(out / "stars" / name)
    (out / "stars" / "report.json").mkdir()
    before = snapshot(out / "stars")
    result = cm("batch", listing, "--out-dir", out, "--jobs", "2")
    assert result.returncode == 1, result.stderr
    assert snapshot(out / "stars") == before
    report = strict_json(out / "batch.json")
    assert (report["ok"], report["bad_input"], report["internal_failure"], report["exit_code"]) == (3, 1, 1, 1)
    stars = next(job for job in report["jobs"] if job["name"] == "stars")
    assert stars["status"] == "internal_failure" and stars["exit_code"] == 1
    assert stars["message"] == f"cannot replace {out / 'stars' / 'report.json'}: it is a directory"
    assert leftovers(out) == [] and leftovers(out / "stars") == []


@pytest.mark.parametrize("text, line, error", [
    ("a.xy b.xy\na.xy missing.xy\n", 2, "missing.xy: No such file or directory"),
    ("a.xy b.xy\n\n# one input:\nb.xy  # a.xy\n", 4, "a job needs at least two input files, got 1"),
    ("x: a.xy b.xy\nx: b.xy a.xy\n", 2, "the job folder 'x' is already line 1's; name the job "
                                         "with a leading 'NAME:' field"),
    ("a.xy b.xy\n1-a: b.xy a.xy\n", 2, "the job folder '1-a' is already line 1's; name the job "
                                        "with a leading 'NAME:' field"),
    ("sub/dir: a.xy b.xy\n", 1, "'sub/dir:' is not a job name (one folder name, not starting "
                                "with '.', not batch.json)"),
    ("batch.json: a.xy b.xy\n", 1, "'batch.json:' is not a job name (one folder name, not "
                                   "starting with '.', not batch.json)"),
    ("a.xy .\n", 1, "./. is a directory, not a polygon file"),
    ("# nothing\n\n", None, "no jobs (one line per job: its input files)"),
])
def test_malformed_list_is_one_line_and_writes_nothing(cm, tmp_path, text, line, error):
    write_xy(tmp_path / "a.xy", SQUARE)
    write_xy(tmp_path / "b.xy", KITE)
    (tmp_path / "list.txt").write_text(text)
    out = tmp_path / "out"
    out.mkdir()
    (out / "batch.json").write_text("{}\n")  # an earlier batch's
    before = snapshot(tmp_path)
    result = cm("batch", "./list.txt", "--out-dir", out, "-j", "2")
    assert result.returncode == 2
    where = "./list.txt" if line is None else f"./list.txt:{line}"
    expected = error if error.startswith("./.") else error.replace("missing.xy", "./missing.xy")
    assert result.stderr == f"compatmesh: {where}: {expected}\n"
    assert result.stdout == ""
    assert snapshot(tmp_path) == before


@pytest.mark.parametrize("args, error", [
    (["--out-dir", "out"], "batch: LIST is required (see 'compatmesh batch --help')"),
    (["list.txt"], "batch: --out-dir DIR is required (see 'compatmesh batch --help')"),
    (["list.txt", "list.txt", "-o", "out"],
     "batch: takes one LIST, got 'list.txt' and 'list.txt' (the inputs of a job go on its line of LIST)"),
    (["list.txt", "-o", "out", "--jobs", "0"], "batch: --jobs needs a whole number in [1, 4096], got '0'"),
    (["list.txt", "-o", "out", "--progress"],
     "batch: unknown option '--progress' (see 'compatmesh batch --help')"),
    (["list.txt", "-o", "out", "--pin", "0,1,2"], "list.txt:1: --pin 0,1,2 names 3 vertices for 2 inputs"),
    (["list.txt", "-o", "out", "--format", "stl"], "batch: unknown --format 'stl' (known: off, obj, ply)"),
])
def test_bad_command_line(cm, tmp_path, args, error):
    write_xy(tmp_path / "a.xy", SQUARE)
    write_xy(tmp_path / "b.xy", KITE)
    (tmp_path / "list.txt").write_text("a.xy b.xy\n")
    result = cm("batch", *args)
    assert result.returncode == 2
    assert result.stderr == f"compatmesh: {error}\n"
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("list_name", ["list.txt", "batch.json"])
def test_batch_json_never_replaces_an_input(cm, tmp_path, list_name):
    """DIR/batch.json is an input (or the list itself): refused before
    anything is written or removed."""
    out = tmp_path / "out"
    out.mkdir()
    write_xy(out / "batch.json" if list_name == "list.txt" else tmp_path / "a.xy", SQUARE)
    write_xy(tmp_path / "b.xy", KITE)
    first = "batch.json" if list_name == "list.txt" else "../a.xy"
    (out / list_name).write_text(f"{first} ../b.xy\n")
    before = snapshot(tmp_path)
    result = cm("batch", out / list_name, "--out-dir", out)
    assert result.returncode == 2
    report = out / "batch.json"
    assert result.stderr == f"compatmesh: {report} would replace the input {report}; choose another output\n"
    assert snapshot(tmp_path) == before


def test_batch_help(cm):
    result = cm("batch", "--help")
    assert result.returncode == 0 and result.stderr == ""
    assert result.stdout.startswith("Usage: compatmesh batch LIST --out-dir DIR")
    for option in ("--out-dir", "--jobs", "--format", "--min-angle", "--quiet", "--help"):
        assert re.search(rf"^\s+(-\w, )?{option}\b", result.stdout, re.MULTILINE), option
    for word in ("NAME:", "LINE-STEM", "batch.json", "bad_input", "internal_failure", "130"):
        assert word in result.stdout
    assert re.search(r"^\s+batch\s", cm("--help").stdout, re.MULTILINE)


@pytest.mark.parametrize("signum", [signal.SIGINT, signal.SIGTERM], ids=["SIGINT", "SIGTERM"])
def test_signal_leaves_only_complete_folders(compatmesh_path, tmp_path, signum):
    """Ten jobs of about a quarter second each on two workers; the signal
    comes once the first job has reported, while others are running."""
    jobs = 10
    for i in range(jobs):
        write_xy(tmp_path / f"p{i}.xy", star(1000, 100 + i))
        write_xy(tmp_path / f"q{i}.xy", star(1000, 200 + i))
    (tmp_path / "list.txt").write_text("".join(f"p{i}.xy q{i}.xy\n" for i in range(jobs)))
    out = tmp_path / "out"
    out.mkdir()
    (out / "batch.json").write_text("{}\n")  # an earlier batch's: it no longer applies
    process = subprocess.Popen([compatmesh_path, "batch", str(tmp_path / "list.txt"), "--out-dir", str(out),
                                "--jobs", "2"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                               encoding="utf-8")
    try:
        first = process.stderr.readline()
        assert " ok: " in first, first
        process.send_signal(signum)
        # Read through the same buffered stream as the first line: lines
        # already buffered with it would be missed by communicate().
        rest = process.stderr.read()
        process.wait(timeout=60)
    finally:
        process.kill()
    assert process.returncode == 130, rest
    lines = [first, *rest.splitlines(keepends=True)]
    assert all(" ok: " in line for line in lines[:-1]), lines
    done = len(lines) - 1
    assert re.fullmatch(rf"compatmesh: batch: interrupted; {done} of {jobs} jobs had succeeded \(their "
                        r"folders are complete\), the others left nothing; batch.json not written\n",
                        lines[-1])
    assert done < jobs
    folders = sorted(os.listdir(out))
    assert len(folders) == done
    for folder in folders:
        i = int(folder.split("-")[0]) - 1
        assert folder == f"{i + 1}-p{i}"
        assert sorted(os.listdir(out / folder)) == sorted([f"p{i}.off", f"q{i}.off", "report.json",
                                                           "preview.svg", "preview.png"])
        assert strict_json(out / folder / "report.json")["valid"] is True
    assert leftovers(out) == []
