"""The docs build's generator (mkdocs-gen-files runs it): the reference pages and the
performance page's figures, made from the code at each build, so none can go stale."""

from __future__ import annotations

import sys
from pathlib import Path

import mkdocs_gen_files

sys.path.insert(0, str(Path(__file__).resolve().parent))

import performance  # noqa: E402
import reference_batch  # noqa: E402
import reference_cli  # noqa: E402
import reference_fidelity  # noqa: E402
import reference_launch  # noqa: E402
import reference_parameters  # noqa: E402
import reference_python  # noqa: E402
import reference_types  # noqa: E402

for name, module in (("cli", reference_cli), ("launch-files", reference_launch),
                     ("types", reference_types), ("fidelity", reference_fidelity),
                     ("parameters", reference_parameters),
                     ("python-apis", reference_python), ("batch-file", reference_batch)):
    with mkdocs_gen_files.open(f"reference/{name}.md", "w") as page:
        page.write(module.page())

with mkdocs_gen_files.open("performance.md", "a") as page:
    page.write(performance.section())
