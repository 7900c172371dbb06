"""How a signal stops a command: SIGTERM and SIGHUP unwind it as Ctrl-C does (engines killed, files removed), and a
stop is never lost, even when its handler ran where Python ignores exceptions."""
import signal
import sys
import threading

REDELIVER_S = 0.05      # a lost stop is raised again this long after it was lost, outside the code that lost it


class Stopped(KeyboardInterrupt):
    """SIGTERM or SIGHUP, raised where harness is so that it unwinds as for Ctrl-C: engines killed, files removed."""

    def __init__(self, signum):
        super().__init__(signum)
        self.signum = signum


def stop_on_signals():
    """SIGTERM and SIGHUP stop harness the way Ctrl-C does, and lost stops are raised again (both only where the
    main thread runs the command: only it receives signals); returns (what raises a lost stop not yet raised again,
    what restores the handlers replaced)."""
    if threading.current_thread() is not threading.main_thread():
        return (lambda: None), (lambda: None)

    def stop(signum, frame):
        raise Stopped(signum)
    replaced = {signum: signal.signal(signum, stop) for signum in (signal.SIGTERM, signal.SIGHUP)}
    raise_lost, restore_redelivery = redeliver_lost_stops()

    def restore():
        restore_redelivery()
        for signum, handler in replaced.items():
            signal.signal(signum, handler)
    return raise_lost, restore


def stop_behind(exc):
    """The stop (KeyboardInterrupt, Stopped included) that `exc` was raised from or while handling, if any: a C
    extension interrupted while it loads turns the stop into an ImportError caused by it, and an error raised
    while a stop unwinds has it as its context."""
    seen = set()
    while exc is not None and id(exc) not in seen:
        if isinstance(exc, KeyboardInterrupt):
            return exc
        seen.add(id(exc))
        exc = exc.__cause__ or exc.__context__
    return None


def redeliver_lost_stops():
    """A stop raised where Python ignores exceptions (a handler run at a fork, a finaliser: "Exception ignored in
    ...") would be lost, and harness would carry on as if never asked to stop. Such a stop is raised again, by a
    timer's SIGALRM, once the main thread is out of that code, or when the command ends, if that comes first.
    Returns (what raises a lost stop not yet raised again, what restores the previous hook and SIGALRM handler)."""
    lost = []
    previous_hook, previous_alarm = sys.unraisablehook, signal.getsignal(signal.SIGALRM)

    def hook(unraisable):
        if not isinstance(unraisable.exc_value, KeyboardInterrupt):
            previous_hook(unraisable)
            return
        stop = unraisable.exc_value
        lost.append(stop.signum if isinstance(stop, Stopped) else signal.SIGINT)
        signal.setitimer(signal.ITIMER_REAL, REDELIVER_S)

    def again(signum=None, frame=None):
        """The lost stop raised again, once: by the timer, or by the command's end if that comes first."""
        if lost:
            signum = lost[-1]
            lost.clear()
            raise KeyboardInterrupt if signum == signal.SIGINT else Stopped(signum)

    sys.unraisablehook = hook
    signal.signal(signal.SIGALRM, again)

    def restore():
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous_alarm)
        sys.unraisablehook = previous_hook
    return again, restore
