"""examples/tour.ipynb executed top to bottom with nbclient (Debian's python3-nbclient and
python3-ipykernel), as a user's Jupyter would: every cell runs, and what it shows is checked."""
import os
import pathlib
import re

import nbclient
import nbformat

NOTEBOOK = pathlib.Path(__file__).resolve().parents[2] / "examples" / "tour.ipynb"


def test_the_tour_notebook_runs_and_shows_its_results():
    notebook = nbformat.read(NOTEBOOK, as_version=4)
    os.environ.setdefault("PYDEVD_DISABLE_FILE_VALIDATION", "1")  # the kernel's debugger notice
    nbclient.NotebookClient(notebook, timeout=600, kernel_name="python3").execute()
    code = [c for c in notebook.cells if c.cell_type == "code"]
    text = ["".join(o.get("text", "") for o in c.outputs) for c in code]
    html = ["".join(o.get("data", {}).get("text/html", "") for o in c.outputs) for c in code]
    assert not any(o.output_type == "error" for c in code for o in c.outputs)
    # The paper's story: the unoptimised program falls, the evolved one walks farther, standing.
    walked = re.search(r"unoptimized: walked ([0-9.]+), fell: True\nevolved: +walked ([0-9.]+), "
                       r"fell: False", text[1])
    assert walked and float(walked.group(2)) > float(walked.group(1)), text[1]
    # The map as a data frame in pyribs' columns, shown as a table.
    assert re.search(r"^[0-9]+ cells filled", text[2])
    assert "<table" in html[2] and "objective" in html[2] and "measures_0" in html[2]
    # Adaptation says how many trials and what the adapted gait walks.
    assert re.search(r"[0-9]+ trials \(.*\); the adapted gait walks [0-9.]+ on the damaged", text[3])
    # The replay page inline, in a sandboxed frame, naming the damage.
    assert html[4].startswith("<iframe sandbox=") and "damaged (red): right_front:locked" in html[4]
