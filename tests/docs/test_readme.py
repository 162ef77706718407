"""The README is the short front page issue 38 asks for: at most 150 lines, the two
quick-start commands unchanged (``.ci/run`` calls the test one), and every relative link
in it names a file of the repository (the README is read on the forge, outside the docs
site, so the site's link check does not see it)."""
import re

from ancf.common.paths import REPO

README = (REPO / "README.md").read_text(encoding="utf-8")
MAX_LINES = 150


def _relative_links(text: str) -> list[str]:
    """The targets of the Markdown links and images that are not web addresses or anchors."""
    targets = re.findall(r"\]\(([^)\s]+)\)", text)
    return [t for t in targets if not re.match(r"[a-z]+:", t) and not t.startswith("#")]


def test_the_readme_is_short():
    assert len(README.splitlines()) <= MAX_LINES


def test_the_quick_start_is_the_two_make_commands_and_ci_runs_the_test_one():
    block = README.split("## Quick start", 1)[1].split("```sh\n", 1)[1].split("```", 1)[0]
    assert [line.split("#")[0].strip() for line in block.splitlines()] == ["make reports",
                                                                          "make test"]
    ci = (REPO / ".ci" / "run").read_text(encoding="utf-8")
    assert ci.strip().splitlines()[-1] == "make test"


def test_every_relative_link_of_the_readme_names_a_file():
    links = _relative_links(README)
    assert len(links) >= 20
    missing = [t for t in links if not (REPO / t.split("#", 1)[0]).is_file()]
    assert missing == []


def test_the_link_check_sees_a_missing_file():
    assert _relative_links("[a](docs/nope.md) [b](https://x.org) [c](#top) ![d](e.png)") == [
        "docs/nope.md", "e.png"]
