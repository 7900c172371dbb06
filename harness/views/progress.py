"""Progress of a long command on stderr: a live bar on a terminal (rich: done/total, what just finished, elapsed and
time left), one plain line per step elsewhere (a CI log keeps them) once the command has taken a couple of seconds;
nothing when quiet."""
import sys
import time

QUIET_START_S = 2.0       # plain lines only after this long: a quick command prints none


class Progress:
    """Steps expected (expect) and done (advance), each with the words of what it was."""

    def __init__(self, title, quiet=False, stream=None):
        self.title, self.quiet = title, quiet
        self.stream = stream or sys.stderr
        self.total, self.done, self.start = 0, 0, time.perf_counter()
        self.live = None
        if not quiet and self.stream.isatty():
            from rich.console import Console
            from rich.progress import (BarColumn, MofNCompleteColumn, Progress as Bar, TextColumn, TimeElapsedColumn,
                                       TimeRemainingColumn)
            self.live = Bar(TextColumn("[bold]{task.fields[title]}"), BarColumn(), MofNCompleteColumn(),
                            TimeElapsedColumn(), TextColumn("left"), TimeRemainingColumn(),
                            TextColumn("{task.fields[what]}"), console=Console(file=self.stream), transient=True)
            self.live.start()
            self.task = self.live.add_task("", total=0, title=title, what="")

    def expect(self, steps):
        """Add `steps` to the total."""
        self.total += steps
        if self.live is not None:
            self.live.update(self.task, total=self.total)

    def advance(self, what):
        """One step done: `what` it was."""
        self.done += 1
        if self.quiet:
            return
        if self.live is not None:
            self.live.update(self.task, advance=1, what=what)
            return
        elapsed = time.perf_counter() - self.start
        if elapsed < QUIET_START_S:
            return
        left = elapsed / self.done * (self.total - self.done) if self.total > self.done else 0.0
        print(f"harness: {self.title} [{self.done}/{self.total}] {elapsed:.1f} s, about {left:.0f} s left: {what}",
              file=self.stream, flush=True)

    def close(self):
        if self.live is not None:
            self.live.stop()
            self.live = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
