"""The Python module against the command line: same bits, same messages, no leaks.

Run by CTest (python_module) with the built module on PYTHONPATH and HEXGAIT_BIN naming the
`hexgait` binary of the same build.
"""
import json
import os
import pathlib
import subprocess
import sys

import numpy as np
import pytest

import hexgait

HEXGAIT = os.environ["HEXGAIT_BIN"]
DATA = pathlib.Path(__file__).resolve().parent.parent / "data"
EVOLVED = str(DATA / "evolved_seed1.genome")


def cli(*args):
    """`hexgait ARGS`: (exit code, stdout, the error message without its 'hexgait: error: ')."""
    done = subprocess.run([HEXGAIT, *args], capture_output=True, text=True)
    return done.returncode, done.stdout, done.stderr.strip().removeprefix("hexgait: error: ")


def cli_json(*args):
    code, out, err = cli("simulate", "--json", *args)
    assert code == 0, err
    return json.loads(out)


def random_genomes(n, seed=1, genes=120):
    return np.random.default_rng(seed).integers(-8, 8, size=(n, genes), dtype=np.int8)


# --- the same bits as the command line ------------------------------------------------------

@pytest.mark.parametrize("genome", [None, EVOLVED], ids=["unoptimized", "evolved"])
def test_evaluate_and_simulate_equal_the_command_line(genome):
    reference = cli_json(*(["--genome", genome] if genome else ["--unoptimized"]))
    genes = np.zeros((1, 120), np.int8) if genome is None else hexgait.load_genome(genome)[None, :]
    batch = hexgait.Evaluator().evaluate(np.repeat(genes, 3, axis=0))
    run = hexgait.simulate(genome)
    for i in range(3):
        assert batch["distance"][i] == reference["distance"]  # bit for bit
        assert batch["fell"][i] == reference["fell"]
        assert batch["diverged"][i] == reference["diverged"]
    assert run["distance"] == reference["distance"]
    assert run["fell"] == reference["fell"]
    assert run["fall_time"] == reference["fall_time"]
    assert run["fall_cycle"] == reference["fall_cycle"]
    duty = reference["duty_factors"]  # in the creature's leg order
    assert len(duty) == len(reference["legs"]) == 6 and all(0 <= d <= 1 for d in duty)
    assert run["duty_factors"] == duty
    assert batch["duty_factors"].shape == (3, 6)
    assert batch["duty_factors"][2].tolist() == duty
    if reference["fell"]:
        assert batch["fall_time"][0] == reference["fall_time"]
        assert batch["fall_cycle"][0] == reference["fall_cycle"]


def test_the_paper_story():
    """Unoptimized: falls by its third cycle; the evolved genome walks further and stays up."""
    result = hexgait.Evaluator().evaluate(np.stack([np.zeros(120, np.int8),
                                                    hexgait.load_genome(EVOLVED)]))
    assert result["fell"][0] and 1 <= result["fall_cycle"][0] <= 3
    assert not result["fell"][1]
    assert result["distance"][1] > result["distance"][0]


def test_offsets_equal_genes_times_the_step():
    evaluator = hexgait.Evaluator(time=50)
    assert evaluator.time == 50
    genomes = random_genomes(8, seed=3)
    by_genes = evaluator.evaluate(genomes)
    # A standing run lasts the evaluator's time: what a script divides by for a share of the test.
    standing = ~np.asarray(by_genes["fell"], dtype=bool)
    assert standing.any()
    np.testing.assert_allclose(np.asarray(by_genes["end_time"])[standing], evaluator.time)
    by_offsets = evaluator.evaluate_offsets(genomes.astype(np.float64) * evaluator.gene_length_step)
    for key in ("distance", "fell", "fall_time", "steps", "max_tilt_degrees"):
        np.testing.assert_array_equal(by_genes[key], by_offsets[key])


@pytest.mark.parametrize("precision", ["double", "float"])
def test_batch_size_and_threads_do_not_change_results(precision):
    genomes = random_genomes(21, seed=7)
    reference = hexgait.Evaluator(time=60, precision=precision, threads=1).evaluate(genomes)
    for threads in (2, 3):
        whole = hexgait.Evaluator(time=60, precision=precision, threads=threads).evaluate(genomes)
        np.testing.assert_array_equal(whole["distance"], reference["distance"])
    evaluator = hexgait.Evaluator(time=60, precision=precision, threads=2)
    one_by_one = [evaluator.evaluate(g[None, :])["distance"][0] for g in genomes]
    np.testing.assert_array_equal(np.array(one_by_one), reference["distance"])
    halves = np.concatenate([evaluator.evaluate(genomes[:5])["distance"],
                             evaluator.evaluate(genomes[5:])["distance"]])
    np.testing.assert_array_equal(halves, reference["distance"])
    if precision == "double":  # the scalar path too
        scalar = hexgait.Evaluator(time=60, batch_lanes=1, threads=2).evaluate(genomes)
        np.testing.assert_array_equal(scalar["distance"], reference["distance"])


def test_float_matches_the_command_line_float_run(tmp_path):
    """evolve --precision float and the float evaluator agree on a genome's fitness."""
    code, _, err = cli("evolve", "--precision", "float", "--generations", "1", "--population", "4",
                       "--time", "40", "--seed", "2", "--quiet", "--out", str(tmp_path / "run"))
    assert code == 0, err
    best = hexgait.load_genome(str(tmp_path / "run" / "best.genome"))
    fitness = (tmp_path / "run" / "fitness.csv").read_text().splitlines()
    header, last = fitness[0].split(","), fitness[-1].split(",")
    best_fitness = float(last[header.index("best")])
    got = hexgait.Evaluator(time=40, precision="float").evaluate(best[None, :])["distance"][0]
    assert f"{got:.4f}" == f"{best_fitness:.4f}"


def test_simulate_trace_and_positions():
    run = hexgait.simulate(time=10, interval=0.5, positions_at=[0, 5, 2.5])
    assert run["time"].shape == (21,) and run["centre"].shape == (21, 3)
    assert run["feet_on_ground"].shape == (21, 6) and run["feet_on_ground"].dtype == np.bool_
    assert run["positions"].shape == (3, hexgait.Creature().particles, 3)
    np.testing.assert_array_equal(run["positions_time"], [0, 5, 2.5])
    assert np.all(run["positions"][:, :, 2] > -0.05)  # nothing sinks through the ground
    assert run["positions"][1, 0, 0] != run["positions"][0, 0, 0]  # it moved
    # The CSV trace of the command line, row for row at its printed precision.
    code, out, err = cli("simulate", "--time", "10", "--csv", "-", "--csv-interval", "0.5")
    assert code == 0, err
    rows = [line.split(",") for line in out.splitlines()[1:]]
    assert len(rows) == len(run["time"])
    for row, x, z in zip(rows, run["centre"][:, 0], run["lowest_body"]):
        assert row[1] == f"{x:.6f}" and row[4] == f"{z:.6f}"


def test_genome_files_round_trip(tmp_path):
    genome = random_genomes(1, seed=11)[0]
    path = tmp_path / "g.genome"
    hexgait.save_genome(str(path), genome, comment="from a test")
    np.testing.assert_array_equal(hexgait.load_genome(str(path)), genome)
    reference = cli_json("--genome", str(path), "--time", "30")
    assert hexgait.Evaluator(time=30).evaluate(genome)["distance"][0] == reference["distance"]
    symmetric = np.arange(60, dtype=np.int8) % 16 - 8
    hexgait.save_genome(str(tmp_path / "s.genome"), symmetric)
    np.testing.assert_array_equal(hexgait.load_genome(str(tmp_path / "s.genome")), symmetric)
    # An output that is one of the call's inputs is refused, as on the command line, and the
    # input is left as it was.
    creature = tmp_path / "hexapod.json"
    creature.write_bytes((DATA.parent.parent / "assets" / "hexapod.json").read_bytes())
    before = creature.read_bytes()
    with pytest.raises(ValueError, match="is the same file as the input"):
        hexgait.save_genome(str(creature), genome, creature=str(creature))
    assert creature.read_bytes() == before
    # A line break in the comment stays in one comment line: the file reads back.
    hexgait.save_genome(str(path), genome, comment="two\nlines")
    np.testing.assert_array_equal(hexgait.load_genome(str(path)), genome)


def test_the_second_creature():
    wedge = hexgait.Creature("wedge")
    assert wedge.name == "wedge" and "wedge" in hexgait.builtin_creatures
    evaluator = hexgait.Evaluator(creature=wedge, time=30)
    reference = cli_json("--creature", "wedge", "--time", "30")
    assert evaluator.evaluate(np.zeros((1, evaluator.genes), np.int8))["distance"][0] == \
        reference["distance"]


def test_a_movie_from_python_draws_no_progress_bar(tmp_path):
    """The library never draws: a progress bar is the command's. With stderr on a terminal (a
    pseudo-terminal here), render_movie writes nothing to it."""
    import pty
    leader, follower = pty.openpty()
    code = ("import hexgait; hexgait.render_movie(%r, time=20, size='96x64', fps=10)"
            % str(tmp_path / "m.mp4"))
    subprocess.run([sys.executable, "-c", code], stderr=follower, check=True,
                   env=dict(os.environ))
    os.close(follower)
    written = b""
    try:
        while True:
            chunk = os.read(leader, 4096)
            if not chunk:
                break
            written += chunk
    except OSError:  # EIO once the pseudo-terminal has no writer left
        pass
    os.close(leader)
    assert written == b"", written[:200]
    assert (tmp_path / "m.mp4").stat().st_size > 1000


def test_render_still_and_movie(tmp_path):
    frame = hexgait.render_still(size="160x120", time=2.0, genome=hexgait.load_genome(EVOLVED))
    assert frame.shape == (120, 160, 3) and frame.dtype == np.uint8
    assert frame.reshape(-1, 3).std(axis=0).max() > 10  # a picture, not a blank
    movie = tmp_path / "m.mp4"
    assert hexgait.render_movie(str(movie), time=2, size="160x120", fps=10) == str(movie)
    assert movie.stat().st_size > 1000
    with pytest.raises(ValueError, match="size"):
        hexgait.render_still(size="12x12")
    with pytest.raises(TypeError):  # a misspelt option is not passed on as a flag
        hexgait.render_still(sise="160x120")


def test_replay_html_is_the_commands_page(tmp_path):
    page = hexgait.replay_html(genome=EVOLVED, time=100, view="side", cues="footprints,strip")
    out = tmp_path / "r.html"
    subprocess.run([HEXGAIT, "replay", "--genome", EVOLVED, "--time", "100", "--view", "side",
                    "--cues", "footprints,strip", "--out", str(out)], check=True,
                   capture_output=True)
    assert page == out.read_text(encoding="utf-8")
    assert page.startswith("<!DOCTYPE html>") and "http://" not in page and "https://" not in page
    with pytest.warns(UserWarning, match="keeping one in"):
        hexgait.replay_html(time=20000)  # 9,092 movie frames: one in 2 kept
    with pytest.raises(ValueError, match="at most"):
        hexgait.replay_html(time=500000)
    with pytest.raises(ValueError, match="--view"):
        hexgait.replay_html(view="below")


def test_adapt_is_the_commands_trials(tmp_path):
    rep, out = tmp_path / "rep", tmp_path / "a"
    subprocess.run([HEXGAIT, "repertoire", "--evaluations", "100", "--batch", "50", "--time", "200",
                    "--no-movie", "--compare-ga", "0", "--quiet", "--out", str(rep)], check=True,
                   capture_output=True)
    result = hexgait.adapt(str(rep), damage="right_middle:locked", length_scale=0.2)
    subprocess.run([HEXGAIT, "adapt", "--repertoire", str(rep), "--damage", "right_middle:locked",
                    "--length-scale", "0.2", "--no-movie", "--out", str(out)], check=True,
                   capture_output=True)
    rows = (out / "trials.csv").read_text().splitlines()[1:]
    assert [float(r.split(",")[5]) for r in rows] == [t["distance"] for t in result["trials"]]
    assert [int(r.split(",")[1]) for r in rows] == [t["elite"] for t in result["trials"]]
    assert result["damaged_distance"].max() >= result["adapted_distance"]
    assert len(result["intact_distance"]) == len(result["damaged_distance"]) > 0
    # stop=None runs every trial: the first are the stopped run's, and at_stop_rule is its result.
    full = hexgait.adapt(str(rep), damage="right_middle:locked", length_scale=0.2, stop=None)
    assert len(full["trials"]) == 20
    assert [t["elite"] for t in full["trials"][:len(result["trials"])]] == \
        [t["elite"] for t in result["trials"]]
    assert result["at_stop_rule"] is None
    if result["stopped"].startswith("the best trial reached"):
        assert full["at_stop_rule"]["trials"] == len(result["trials"])
        assert full["at_stop_rule"]["adapted_distance"] == result["adapted_distance"]
        assert full["at_stop_rule"]["random_best"] == result["random_best"]
        assert full["at_stop_rule"]["ga_best"] == result["ga_best"]
    assert [r.split(",")[-1] for r in rows] == ["intact"] * len(rows) == \
        [t["prior"] for t in result["trials"]] and result["library"] == []
    with pytest.raises(ValueError, match="unknown leg"):
        hexgait.adapt(str(rep), damage="middle:locked")
    # The repertoire's creature and program named as the command's --creature and --motor.
    named = hexgait.adapt(str(rep), damage="right_middle:locked", length_scale=0.2,
                          creature="hexapod")
    assert [t["distance"] for t in named["trials"]] == [t["distance"] for t in result["trials"]]
    # adapt() draws no figure, so it needs no gnuplot (the command, which does, checks for it).
    path = os.environ["PATH"]
    os.environ["PATH"] = str(tmp_path)
    try:
        no_gnuplot = hexgait.adapt(str(rep), damage="right_middle:locked", length_scale=0.2)
    finally:
        os.environ["PATH"] = path
    assert [t["distance"] for t in no_gnuplot["trials"]] == [t["distance"] for t in result["trials"]]
    assert not result["damaged_diverged"].any() and not any(t["diverged"] for t in result["trials"])
    assert (result["damaged_fell"] == (np.array(
        [r.split(",")[-2] for r in (out / "elites.csv").read_text().splitlines()[1:]]) == "1")).all()
    code, _, message = cli("adapt", "--repertoire", str(rep), "--damage", "right_middle:locked",
                           "--creature", "wedge", "--no-movie", "--out", str(tmp_path / "w"))
    assert code != 0
    with pytest.raises(ValueError) as error:
        hexgait.adapt(str(rep), damage="right_middle:locked", creature="wedge")
    assert str(error.value) == message
    with pytest.raises(ValueError, match="give the intact creature"):
        hexgait.adapt(str(rep), damage="right_middle:locked",
                      creature=hexgait.Creature("hexapod", damage="right_middle:locked"))


def test_adapt_with_a_library_of_damages(tmp_path):
    # `adapt --library` runs every elite on every leg with each default injury but the damage
    # itself, and its loop is trial_and_error's on those runs (each trial's descriptor the
    # damaged creature's duty factors, as Evaluator measures them); adapt(library=[...]) takes a
    # library of other injuries the same way.
    rep = tmp_path / "rep"
    subprocess.run([HEXGAIT, "repertoire", "--evaluations", "40", "--batch", "20", "--time", "100",
                    "--no-movie", "--compare-ga", "0", "--quiet", "--out", str(rep)], check=True,
                   capture_output=True)
    damage = "right_middle:locked"
    subprocess.run([HEXGAIT, "adapt", "--repertoire", str(rep), "--damage", damage, "--library",
                    "--no-stop", "--trials", "6", "--no-movie", "--out", str(tmp_path / "a")],
                   check=True, capture_output=True)
    record = json.loads((tmp_path / "a" / "adapt.json").read_text())
    names = record["library"]
    legs = ["right_rear", "right_middle", "right_front", "left_rear", "left_middle", "left_front"]
    assert names == [f"{leg}:{kind}" for leg in legs for kind in hexgait.damage_library_kinds
                     if f"{leg}:{kind}" != damage]  # the damage itself left out
    frame = hexgait.load_archive(str(rep))
    genes = frame[[c for c in frame.columns if c.startswith("solution_")]].to_numpy()
    descriptors = frame[[c for c in frame.columns if c.startswith("measures_")]].to_numpy()
    intact = frame["objective"].to_numpy()

    def runs(name):
        evaluator = hexgait.Evaluator(creature=hexgait.Creature(damage=name), time=100,
                                      stop_at_fall=True)
        r = evaluator.evaluate(genes)
        return r["distance"], r["duty_factors"]

    truth, shown = runs(damage)
    library = {name: runs(name) for name in names}
    loop = hexgait.trial_and_error(descriptors, intact, truth, library=library, shown=shown,
                                   stop=None, trials=6)
    rows = [r.split(",") for r in (tmp_path / "a" / "trials.csv").read_text().splitlines()[1:]]
    assert [(int(r[1]), r[-1]) for r in rows] == [(t["elite"], t["prior"]) for t in loop["trials"]]
    assert loop["trials"][0]["prior"] == "intact"
    # The command made the library's runs the loop read, no more: a part of them.
    assert record["library_runs"]["made"] == loop["library_runs"]
    assert record["library_runs"]["of"] == len(names) * len(genes) > loop["library_runs"]
    # A callable trial with a library returns the distance and the descriptor the run showed.
    called = hexgait.trial_and_error(descriptors, intact, lambda i: (truth[i], shown[i]),
                                     library=library, stop=None, trials=6)
    assert called["trials"] == loop["trials"]
    # From Python, a library of the injuries given: every other leg locked.
    result = hexgait.adapt(str(rep), damage=damage, library=["locked"], stop=None, trials=6)
    locked = [f"{leg}:locked" for leg in legs if leg != "right_middle"]
    assert result["library"] == locked
    assert (result["damaged_distance"] == truth).all()
    subset = hexgait.trial_and_error(descriptors, intact, truth, shown=shown, stop=None, trials=6,
                                     library={name: library[name] for name in locked})
    assert [(t["elite"], t["prior"]) for t in result["trials"]] == \
        [(t["elite"], t["prior"]) for t in subset["trials"]]
    assert result["library_runs"] == subset["library_runs"]
    with pytest.raises(ValueError, match="no finite descriptor of 6 values"):
        hexgait.trial_and_error(descriptors, intact, truth, library=library)
    with pytest.raises(ValueError, match="library kind 'left_front:locked'"):
        hexgait.adapt(str(rep), damage=damage, library=["left_front:locked"])
    with pytest.raises(TypeError, match="library must be"):
        hexgait.adapt(str(rep), damage=damage, library="locked")


def read_png(path):
    """An 8-bit RGB or RGBA PNG (as libpng writes hexgait's) as an (H, W, 3) uint8 array."""
    import struct
    import zlib
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, colour, _, _, interlace = header
    assert depth == 8 and colour in (2, 6) and interlace == 0, header
    channels = 3 if colour == 2 else 4
    raw = np.frombuffer(zlib.decompress(idat), np.uint8).reshape(height, width * channels + 1)
    out = np.zeros((height, width * channels), np.int32)
    for y in range(height):
        kind, row = raw[y, 0], raw[y, 1:].astype(np.int32)
        up = out[y - 1] if y else np.zeros_like(row)
        if kind in (0, 2):
            out[y] = (row + (up if kind == 2 else 0)) % 256
            continue
        line = np.zeros_like(row)
        for x in range(row.size):  # Sub, Average and Paeth depend on the pixel to the left
            a = line[x - channels] if x >= channels else 0
            b = up[x]
            c = up[x - channels] if x >= channels else 0
            if kind == 1:
                pred = a
            elif kind == 3:
                pred = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            line[x] = (row[x] + pred) % 256
        out[y] = line
    return out.reshape(height, width, channels)[:, :, :3].astype(np.uint8)


def test_inspect_is_the_commands_report():
    code, out, err = cli("inspect", "--creature", "wedge", "--dt", "0.003")
    assert code == 0, err
    assert hexgait.inspect(creature="wedge", dt=0.003) == out
    assert "smallest margin" in hexgait.inspect()


def test_render_calls_the_library_as_the_commands_do(tmp_path):
    """render_still and render_movie run the commands' own code, not their parsers: the same
    pixels as `hexgait still`, the same bytes as `hexgait render`."""
    png = tmp_path / "still.png"
    code, _, err = cli("still", "--genome", EVOLVED, "--time", "3", "--size", "96x64",
                       "--view", "side", "--cues", "footprints", "--out", str(png))
    assert code == 0, err
    frame = hexgait.render_still(genome=EVOLVED, time=3, size="96x64", view="side",
                                 cues=["footprints"])
    assert np.array_equal(frame, read_png(png))
    made, ours = tmp_path / "cli.mp4", tmp_path / "py.mp4"
    code, _, err = cli("render", "--genome", EVOLVED, "--time", "2", "--size", "96x64", "--fps",
                       "10", "--cues", "all", "--out", str(made))
    assert code == 0, err
    hexgait.render_movie(str(ours), genome=EVOLVED, time=2, size="96x64", fps=10, cues="all")
    assert ours.read_bytes() == made.read_bytes()
    with pytest.raises(ValueError, match="path .* is the same file as the input --genome"):
        hexgait.render_movie(str(made), genome=str(made), time=2, size="96x64")


def test_compare_is_the_commands_check(tmp_path):
    """hexgait.compare gives the verdict and the one-line summary `hexgait compare` prints."""
    a, b = tmp_path / "a.png", tmp_path / "b.png"
    for path, time in ((a, "0"), (b, "2")):
        code, _, err = cli("still", "--size", "96x64", "--time", time, "--out", str(path))
        assert code == 0, err
    same = hexgait.compare(str(a), str(a))
    assert same["match"] and same["different_pixels"] == 0
    code, out, _ = cli("compare", str(a), str(b))
    result = hexgait.compare(str(a), str(b), diff=str(tmp_path / "d.png"))
    assert code == 1 and not result["match"]
    assert out.strip() == result["summary"]
    assert result["diff"] == str(tmp_path / "d.png") and (tmp_path / "d.png").exists()
    assert hexgait.compare(str(a), str(b), tolerance=1.0)["match"]
    with pytest.raises(ValueError, match="--tolerance must be between 0 and 1"):
        hexgait.compare(str(a), str(b), tolerance=-1)
    with pytest.raises(ValueError, match="is not a file"):
        hexgait.compare(str(a), str(tmp_path / "missing.png"))


def test_repertoire_and_load_archive_are_the_commands(tmp_path):
    """repertoire() writes the command's archive; load_archive() reads it as a DataFrame in
    pyribs' layout, equal to archive.csv read by pandas."""
    import pandas as pd
    ours, theirs = tmp_path / "py", tmp_path / "cli"
    hexgait.repertoire(str(ours), evaluations=100, batch=50, time=100)
    code, _, err = cli("repertoire", "--evaluations", "100", "--batch", "50", "--time", "100",
                       "--no-movie", "--compare-ga", "0", "--quiet", "--out", str(theirs))
    assert code == 0, err
    assert (ours / "archive.csv").read_bytes() == (theirs / "archive.csv").read_bytes()
    frame = hexgait.load_archive(str(ours))
    assert list(frame.columns[:3]) == ["index", "objective", "measures_0"]
    assert "solution_119" in frame.columns and frame["solution_0"].dtype == np.int64
    pd.testing.assert_frame_equal(
        frame, pd.read_csv(ours / "archive.csv", float_precision="round_trip"))
    with pytest.raises(ValueError, match="no archive.json there"):
        hexgait.load_archive(str(tmp_path))


def test_pages_and_movies_show_in_notebooks(tmp_path):
    page = hexgait.replay_html(time=5)
    assert isinstance(page, str) and page._repr_html_().startswith("<iframe sandbox=")
    movie = hexgait.render_movie(str(tmp_path / "m.mp4"), time=2, size="96x64", fps=10)
    assert movie == str(tmp_path / "m.mp4")
    assert movie._repr_html_().startswith('<video controls loop style="max-width:100%" '
                                          'src="data:video/mp4;base64,')


# --- bad input: the command line's message, the matching exception ----------------------------

def test_wrong_dtype_is_a_type_error():
    with pytest.raises(TypeError, match="integer array"):
        hexgait.Evaluator(time=1).evaluate(np.zeros((2, 120)))
    with pytest.raises(TypeError):
        hexgait.Evaluator(time=1).evaluate_offsets(np.array([["a"] * 120]))
    with pytest.raises(TypeError):
        hexgait.Evaluator(creature=3)


def test_unsigned_genes_do_not_wrap_into_valid_ones():
    """2^64 - 1 read as a signed integer is -1, a valid gene: it must be refused instead."""
    genes = np.zeros((1, 120), np.uint64)
    genes[0, 5] = np.iinfo(np.uint64).max
    with pytest.raises(ValueError, match=r"\[0, 5\] is 18446744073709551615, outside"):
        hexgait.Evaluator(time=1).evaluate(genes)
    assert hexgait.Evaluator(time=1).evaluate(np.full((1, 120), 7, np.uint64))["distance"].shape \
        == (1,)


def test_the_evaluators_limits_are_the_commands():
    for threads in (-1, 5000):
        code, _, err = cli("evolve", "--threads", str(threads), "--out", "unused")
        with pytest.raises(ValueError) as raised:
            hexgait.Evaluator(time=1, threads=threads)
        assert str(raised.value) == err


@pytest.mark.parametrize("bad, match", [
    (np.zeros((2, 7), np.int8), r"shape \(n, 120\), got \(2, 7\)"),
    (np.zeros((2, 3, 120), np.int8), r"shape"),
    (np.full((1, 120), 9, np.int16), r"is 9, outside \[-8, 7\]"),
    (np.full((1, 120), -9, np.int64), r"is -9, outside"),
])
def test_bad_genomes_are_value_errors(bad, match):
    with pytest.raises(ValueError, match=match):
        hexgait.Evaluator(time=1).evaluate(bad)


@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
def test_non_finite_offsets_are_value_errors(value):
    offsets = np.zeros((2, 120))
    offsets[1, 5] = value
    with pytest.raises(ValueError, match=r"offsets\[1, 5\]"):
        hexgait.Evaluator(time=1).evaluate_offsets(offsets)


def test_an_offset_that_makes_a_length_non_positive():
    with pytest.raises(ValueError, match="non-positive"):
        hexgait.Evaluator(time=1).evaluate_offsets(np.full((1, 120), -100.0))


@pytest.mark.parametrize("kwargs, flags", [
    (dict(integrator="bogus"), ["--integrator", "bogus"]),
    (dict(dt=-1.0), ["--dt", "-1"]),
    (dict(dt=2.0), ["--dt", "2"]),
    (dict(time=float("nan")), ["--time", "nan"]),
    (dict(time=1e9), ["--time", "1e9"]),
])
def test_bad_settings_carry_the_command_line_message(kwargs, flags):
    code, _, message = cli("simulate", *flags)
    assert code != 0
    with pytest.raises(ValueError) as error:
        hexgait.Evaluator(**kwargs)
    assert str(error.value) == message
    with pytest.raises(ValueError) as error:
        hexgait.simulate(**kwargs)
    assert str(error.value) == message


def test_float_needs_euler():
    with pytest.raises(ValueError, match="float needs --integrator euler"):
        hexgait.Evaluator(precision="float", integrator="rk4")
    with pytest.raises(ValueError, match="precision must be"):
        hexgait.Evaluator(precision="half")


def test_missing_files_are_os_errors(tmp_path):
    missing = str(tmp_path / "nope.json")
    code, _, message = cli("simulate", "--creature", missing)
    assert code != 0
    with pytest.raises(OSError) as error:
        hexgait.Creature(missing)
    assert str(error.value) == message
    with pytest.raises(OSError, match="no such file"):
        hexgait.load_genome(str(tmp_path / "nope.genome"))
    with pytest.raises(OSError, match="is a directory"):
        hexgait.load_genome(str(tmp_path))
    with pytest.raises(OSError):
        hexgait.save_genome(str(tmp_path / "no" / "folder" / "g.genome"), np.zeros(120, np.int8))


def test_a_malformed_genome_file_is_a_value_error(tmp_path):
    path = tmp_path / "bad.genome"
    path.write_text("# hexgait genome\nlayout full\nright_rear.hip_low swing 12\n")
    code, _, message = cli("simulate", "--genome", str(path))
    assert code != 0
    with pytest.raises(ValueError) as error:
        hexgait.load_genome(str(path))
    assert str(error.value) == message


# --- Ctrl-C -------------------------------------------------------------------------------------

INTERRUPTED = r"""
import os, signal, sys, threading, time
import numpy as np
import hexgait
what, out = sys.argv[1], sys.argv[2]
threading.Timer(1.0, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
start = time.monotonic()
try:
    if what == "evaluate":  # about 40 s of work on two cores
        hexgait.Evaluator(time=1000).evaluate(np.zeros((4000, 120), np.int8))
    elif what == "one_long_batch":  # one batch of 16 lanes, 40 million steps each: half a minute
        hexgait.Evaluator(time=100000, threads=1).evaluate(np.zeros((16, 120), np.int8))
    elif what == "render_still":  # about a minute of simulation before the frame
        hexgait.render_still(time=900000, allow_long=True)
    elif what == "simulate":  # about 10 s
        hexgait.simulate(time=300000, allow_long=True)
    elif what == "adapt":  # about 12 s: every trial 1.6 million steps
        hexgait.adapt(out, damage="left_rear:short=0.95")
    elif what == "replay_html":  # about 30 s
        hexgait.replay_html(time=110000, dt=0.0005, allow_long=True)
    else:  # about 30 s
        hexgait.render_movie(out, time=100000, size="320x240", allow_long=True)
    print("finished")
except KeyboardInterrupt:
    print(f"interrupted after {time.monotonic() - start:.2f} s")
"""


@pytest.fixture(scope="module")
def long_gaits(tmp_path_factory):
    """A repertoire of 4,000-time-unit gaits (1.5 s to make): adapting it takes seconds."""
    rep = tmp_path_factory.mktemp("long_gaits") / "rep"
    subprocess.run([HEXGAIT, "repertoire", "--evaluations", "32", "--batch", "32", "--time",
                    "4000", "--no-movie", "--compare-ga", "0", "--quiet", "--out", str(rep)],
                   check=True, capture_output=True)
    return rep


@pytest.mark.parametrize("what", ["evaluate", "one_long_batch", "simulate", "render_still",
                                  "render_movie", "adapt", "replay_html"])
def test_ctrl_c_is_honoured_within_about_a_second(tmp_path, what, request):
    """A long call releases the GIL, so Python's own Ctrl-C handler cannot run while it does;
    the call checks for signals between slices, chunks of steps or frames, or trials instead."""
    movie = tmp_path / "long.mp4"
    target = request.getfixturevalue("long_gaits") if what == "adapt" else movie
    done = subprocess.run([sys.executable, "-c", INTERRUPTED, what, str(target)],
                          capture_output=True, text=True, timeout=120)
    assert done.stdout.startswith("interrupted after"), done.stdout + done.stderr
    elapsed = float(done.stdout.split()[2])
    assert elapsed < 2.5, done.stdout  # the signal comes at 1 s
    assert not movie.exists() and list(tmp_path.iterdir()) == []  # no movie, no partial file


AFTERWARDS = r"""
import os, signal, sys, threading, time
import numpy as np
import hexgait
genomes = np.zeros((16, 120), np.int8)
if sys.argv[1:] == ["ignore"]:
    signal.signal(signal.SIGINT, signal.SIG_IGN)
threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT)).start()
try:
    hexgait.Evaluator(time=5000, threads=1).evaluate(genomes)  # about 1.5 s
    print("finished")
except KeyboardInterrupt:
    print("interrupted")
# Python's handler is as it was, and no stop request is left behind: the next call runs whole.
print(signal.getsignal(signal.SIGINT) in (signal.default_int_handler, signal.SIG_IGN))
print(len(hexgait.Evaluator(time=20, threads=1).evaluate(genomes[:2])["distance"]))
"""


@pytest.mark.parametrize("ignored", [False, True], ids=["handled", "ignored"])
def test_a_ctrl_c_leaves_pythons_handler_as_it_was(ignored):
    """While a call runs, SIGINT also stops hexgait's loops and then goes to Python's handler;
    afterwards the handler is Python's again. A SIGINT Python ignores is ignored here too."""
    done = subprocess.run([sys.executable, "-c", AFTERWARDS] + (["ignore"] if ignored else []),
                          capture_output=True, text=True, timeout=60)
    assert done.stdout.split() == ["finished" if ignored else "interrupted", "True", "2"], \
        done.stdout + done.stderr


# --- resources ---------------------------------------------------------------------------------

def resident_kb():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise RuntimeError("no VmRSS")


def test_ten_thousand_small_calls_do_not_grow_memory():
    evaluator = hexgait.Evaluator(time=0.05, threads=2)
    genomes = random_genomes(2, seed=5)
    for _ in range(500):  # warm up allocators and thread pools
        evaluator.evaluate(genomes)
    before = resident_kb()
    for _ in range(10_000):
        evaluator.evaluate(genomes)
    grown = resident_kb() - before
    assert grown < 2048, f"resident memory grew by {grown} kB over 10,000 calls"


# --- the example -------------------------------------------------------------------------------

def test_the_cmaes_example_runs(tmp_path):
    pytest.importorskip("cmaes")
    script = pathlib.Path(__file__).resolve().parents[2] / "examples" / "cmaes_vs_ga.py"
    done = subprocess.run([sys.executable, str(script), "--seeds", "2", "--budgets", "6,20",
                           "--time", "5", "--hexgait", HEXGAIT, "--out", str(tmp_path)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    table = (tmp_path / "table.md").read_text().splitlines()
    assert len(table) == 4 and table[2].startswith("| 6 |") and "of 2 seeds" in table[3]
    rows = (tmp_path / "results.csv").read_text().splitlines()
    assert len(rows) == 1 + 3 * 2 * 2  # header, 3 methods x 2 seeds x 2 budgets
    assert (tmp_path / "cmaes_vs_ga.png").stat().st_size > 10_000


# --- pay only for what is used ----------------------------------------------------------------

def test_gl_and_ffmpeg_load_at_the_first_render(tmp_path):
    """`import hexgait` and an evaluation map neither Mesa nor FFmpeg; a still maps Mesa, a movie
    FFmpeg. In a fresh interpreter, since other tests of this process have rendered."""
    probe = f"""
import sys, numpy as np, hexgait
def mapped(name):
    return any(name in line for line in open('/proc/self/maps'))
def check(when, **expected):
    got = {{name: mapped(name) for name in expected}}
    assert got == expected, (when, got)
check('import', libGL=False, libEGL=False, libOSMesa=False, libavcodec=False, libmpi=False)
hexgait.Evaluator().evaluate(np.zeros((2, 120), np.int8))
check('evaluate', libEGL=False, libOSMesa=False, libavcodec=False, libpng16=False)
hexgait.render_still(size='64x48')
check("render_still", libavcodec=False)
assert mapped("libEGL") or mapped("libOSMesa"), "render_still loaded no GL library"
hexgait.render_movie(r'{tmp_path / "m.mp4"}', time=2, size='64x48')
check('render_movie', libavcodec=True)
"""
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


# --- hexgait.Search: the commands' optimizers, driven from Python -----------------------------

def _without_timing(text):
    """A checkpoint's JSON without what differs between two runs of the same search: wall
    times and the checksum over them."""
    def strip(o):
        if isinstance(o, dict):
            return {k: strip(v) for k, v in o.items() if k not in ("seconds", "checksum")}
        if isinstance(o, list):
            return [strip(v) for v in o]
        return o
    return strip(json.loads(text))


def _ask_evaluate_tell(search, evaluator):
    while not search.done:
        search.tell(evaluator.evaluate_offsets(search.ask()))


@pytest.mark.parametrize("algorithm,flags,kwargs", [
    ("ga", ["--generations", "3"], dict(generations=3)),
    ("cmaes", ["--algorithm", "cmaes", "--generations", "2", "--population", "6"],
     dict(generations=2, population=6)),
], ids=["ga", "cmaes"])
def test_a_search_loop_gives_the_command_s_bytes(tmp_path, algorithm, flags, kwargs):
    out = tmp_path / algorithm
    code, _, err = cli("evolve", "--seed", "5", "--time", "40", "--quiet", "--out", str(out), *flags)
    assert code == 0, err
    evaluator = hexgait.Evaluator(time=40)
    search = hexgait.Search(algorithm, evaluator, seed=5, **kwargs)
    _ask_evaluate_tell(search, evaluator)
    assert _without_timing(search.save()) == _without_timing((out / "checkpoint.json").read_text())
    rows = (out / "fitness.csv").read_text().splitlines()[1:]
    assert [float(r.split(",")[1]) for r in rows] == [h["best"] for h in search.history()]
    best = search.best()
    assert best["distance"] == json.loads((out / "run.json").read_text())["best"]["fitness"]
    assert (best["genes"] is None) == (algorithm == "cmaes")
    # best.genome gives back the best's offsets (genes times the step for the GA) and its walk.
    saved = hexgait.load_genome(str(out / "best.genome"))
    offsets = saved * evaluator.gene_length_step if saved.dtype == np.int8 else saved
    assert offsets.tolist() == best["offsets"].tolist()
    assert evaluator.evaluate_offsets(offsets[None, :])["distance"][0] == best["distance"]


@pytest.mark.parametrize("algorithm,precision,confirm,settings", [
    ("map-elites", "double", False, {}),
    ("map-elites", "float", True, {}),
    ("cma-mae", "float", True, {"emitters": 4, "learning_rate": 0.5}),
    ("iso-line", "double", False, {"sigma_iso": 0.5, "sigma_line": 0.3}),
], ids=["double", "float-confirmed", "cma-mae", "iso-line"])
def test_an_archive_loop_gives_the_command_s_archive(tmp_path, algorithm, precision, confirm,
                                                     settings):
    out = tmp_path / "rep"
    flags = [f"--{k.replace('_', '-')}={v}" for k, v in settings.items()]
    code, _, err = cli("repertoire", "--algorithm", algorithm, "--seed", "2", "--evaluations",
                       "60", "--batch", "20", "--time", "40", "--precision", precision,
                       "--no-movie", "--quiet", "--out", str(out), *flags)
    assert code == 0, err
    evaluator = hexgait.Evaluator(time=40, stop_at_fall=True, precision=precision)
    search = hexgait.Search(algorithm, evaluator, seed=2, evaluations=60, batch=20,
                            confirm_in_double=confirm, **settings)
    _ask_evaluate_tell(search, evaluator)
    assert _without_timing(search.save()) == _without_timing((out / "archive.json").read_text())
    assert len(search.archive()) == search.history()[-1]["filled"]


def test_search_misuse_is_an_error():
    evaluator = hexgait.Evaluator(time=10)
    with pytest.raises(ValueError, match="algorithm 'nsga' is not one of ga, cmaes, map-elites, cma-mae, iso-line"):
        hexgait.Search("nsga", evaluator)
    # A keyword of another algorithm is refused by name, never ignored.
    with pytest.raises(TypeError, match="takes no keyword 'mutation_rate'"):
        hexgait.Search("cma-mae", evaluator, mutation_rate=0.1)
    with pytest.raises(TypeError, match="takes no keyword 'evaluations'"):
        hexgait.Search("ga", evaluator, evaluations=10)
    with pytest.raises(ValueError, match=r"--learning-rate must be in \[0, 1\] for cma-mae"):
        hexgait.Search("cma-mae", evaluator, learning_rate=2)
    # The docstring lists every table's parameters.
    assert "learning_rate=0.1" in hexgait.Search.__doc__
    search = hexgait.Search("ga", evaluator, generations=1)
    with pytest.raises(ValueError, match="no batch was asked for"):
        search.tell(evaluator.evaluate_offsets(np.zeros((4, 120))))
    x = search.ask()
    assert x.shape == (4, 120) and (search.ask() == x).all()  # asking again: the same batch
    with pytest.raises(ValueError, match="3 results for 4 candidates"):
        search.tell(evaluator.evaluate_offsets(x[:3]))
    with pytest.raises(TypeError, match="expected the dict"):
        search.tell({"distance": np.zeros(4)})
    # Results of other candidates, or of the right ones on another creature or run, are refused.
    not_asked = evaluator.evaluate_offsets(x + evaluator.gene_length_step)
    other_run = hexgait.Evaluator(time=20).evaluate_offsets(x)
    for wrong in (not_asked, other_run):
        with pytest.raises(ValueError, match="not the last ask's candidates"):
            search.tell(wrong)
    _ask_evaluate_tell(search, evaluator)
    with pytest.raises(ValueError, match="the search is done"):
        search.ask()
