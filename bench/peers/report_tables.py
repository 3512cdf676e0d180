"""The benchmark's output: markdown tables printed and kept for summary.md, each also written as
a CSV file; and how numbers are shown in them."""
import csv
import pathlib


class Report:
    """Prints markdown tables and keeps them for summary.md; writes CSV files."""

    def __init__(self, out):
        self.out, self.lines = pathlib.Path(out), []
        self.out.mkdir(parents=True, exist_ok=True)

    def say(self, text=""):
        print(text, flush=True)
        self.lines.append(text)

    def table(self, name, header, rows, note=None):
        self.say(f"| {' | '.join(header)} |")
        self.say(f"|{'---|' * len(header)}")
        for row in rows:
            self.say(f"| {' | '.join(str(c) for c in row)} |")
        if note:
            self.say(note)
        self.say()
        with open(self.out / f"{name}.csv", "w", newline="") as f:
            csv.writer(f).writerows([header] + [list(r) for r in rows])

    def close(self):
        (self.out / "summary.md").write_text("\n".join(self.lines) + "\n")


def pct(x, digits=2):
    return f"{100 * x:+.{digits}f} %"


def fmt_s(x):
    return f"{x:.3f}" if x < 10 else f"{x:.2f}"
