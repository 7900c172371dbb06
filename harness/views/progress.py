"""Progress of a long command on stderr: a live bar on a terminal (rich: done/total, what just finished, elapsed and
time left), one plain line per step elsewhere (a CI log keeps them) once the command has taken a couple of seconds;
nothing when quiet."""
import sys
import time

from ..infra.compiling import spent

QUIET_START_S = 2.0       # plain lines only after this long: a quick command prints none


class Progress:
    """Steps expected (expect) and done (advance), each with the words of what it was."""

    def __init__(self, title, quiet=False, stream=None, clock=time.perf_counter, compiling=spent):
        self.title, self.quiet = title, quiet
        self.stream = stream or sys.stderr
        self.clock, self.compiling = clock, compiling
        self.total, self.done, self.start, self.compiled = 0, 0, clock(), compiling()
        self.live = None
        if not quiet and self.stream.isatty():
            from rich.console import Console
            from rich.progress import BarColumn, MofNCompleteColumn, Progress as Bar, TextColumn, TimeElapsedColumn
            self.live = Bar(TextColumn("[bold]{task.fields[title]}"), BarColumn(), MofNCompleteColumn(),
                            TimeElapsedColumn(), TextColumn("{task.fields[left]}"),
                            TextColumn("{task.fields[what]}"), console=Console(file=self.stream), transient=True)
            self.live.start()
            self.task = self.live.add_task("", total=0, title=title, what="", left="")

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
        elapsed, compiled = self.clock() - self.start, self.compiling() - self.compiled
        if self.live is not None:
            self.live.update(self.task, advance=1, what=what, left=self.left(elapsed, compiled))
            return
        if elapsed < QUIET_START_S:
            return
        print(f"harness: {self.title} [{self.done}/{self.total}] {elapsed:.1f} s"
              + (f" ({compiled:.0f} s of it compiling, first use only)" if compiled >= 1.0 else "")
              + f", {self.left(elapsed, compiled)}: {what}", file=self.stream, flush=True)

    def left(self, elapsed, compiled):
        """'about N s left' at the rate of the steps done, the time they spent compiling left out (a first run
        compiles in its first steps: counting it would promise several times the truth)."""
        if self.total <= self.done:
            return "about 0 s left"
        seconds = max(elapsed - compiled, 0.0) / self.done * (self.total - self.done)
        return f"about {seconds:.0f} s left" + (", more if a later step compiles" if compiled >= 1.0 else "")

    def close(self):
        if self.live is not None:
            self.live.stop()
            self.live = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
