"""The progress of a run of :func:`anisotropic_fairing.fair` on stderr (``quiet=False``, the default).

Nothing is shown unless the run lasts longer than ``DELAY`` seconds; then the steps done, the run they
belong to (the default run compares several flows) and the time elapsed are shown: through ``tqdm`` when
it is installed (Debian: python3-tqdm), else as a line that refreshes itself on a terminal, or as a line
per step elsewhere (a log, a notebook's stderr). A thread refreshes the display while the run computes
without the GIL (the set-up before the first step can take seconds on a large mesh). The display never
touches the run: its result is the same, bit for bit, with ``quiet=True``.
"""
import sys
import threading
import time

DELAY = 1.0          # seconds of run before anything is shown
REFRESH = 0.5        # seconds between the refreshes of the display by the thread
SILENCE = 10.0       # line by line (not a terminal): a line after this many seconds without one


class Progress:
    """A run's display: ``with Progress() as p: ... p.step(info) ...`` (``info``: a StepInfo dict)."""

    def __init__(self, file=None, delay=None):
        self.file = sys.stderr if file is None else file
        self.delay = DELAY if delay is None else delay
        self.start = time.monotonic()
        self.lock = threading.Lock()
        self.steps = 0           # steps in all, every run of the call
        self.last = None         # the last step's StepInfo
        self.shown = False
        self.bar = None          # tqdm's bar, when tqdm is there
        self.terminal = False    # without tqdm: a line refreshed in place (a terminal), or a line per step
        self.width = 0           # the refreshed line's length
        self.said = self.start   # line by line: when the last line was written
        self.finished = threading.Event()
        self.thread = threading.Thread(target=self._watch, name='anisotropic_fairing progress', daemon=True)

    def __enter__(self):
        if self.file is not None:
            self.thread.start()
        return self

    def __exit__(self, *exception):
        self.finished.set()
        if self.thread.is_alive():
            self.thread.join()
        with self.lock:
            if self.shown:
                self._close('done' if exception[0] is None else 'interrupted'
                            if issubclass(exception[0], KeyboardInterrupt) else 'ended by ' + exception[0].__name__)

    def step(self, info):
        """The callback's part: one step done."""
        with self.lock:
            self.steps += 1
            self.last = info
            self._show(new_step=True)

    # ---- the display ----------------------------------------------------------------------------

    def _watch(self):
        while not self.finished.wait(REFRESH):
            with self.lock:
                self._show(new_step=False)

    def _text(self):
        info = self.last
        if info is None:
            return 'setting up (topology, noise estimate) and the first step'
        where = 'step %d' % info['step']
        if info.get('runs', 1) > 1:
            where += ' of run %d of at most %d, the %s' % (info['run'], info['runs'], info['run_name'])
        return where

    def _show(self, new_step):
        elapsed = time.monotonic() - self.start
        if self.file is None or elapsed < self.delay:
            return
        try:
            if not self.shown:
                self.shown = True
                self._open()
            if self.bar is not None:
                self.bar.n = self.steps
                self.bar.set_postfix_str(self._text(), refresh=False)
                self.bar.refresh()
            elif self.terminal:
                line = 'anisotropic_fairing: %d steps, %.1f s; %s' % (self.steps, elapsed, self._text())
                width = max(len(line), self.width)
                self.width = len(line)
                self.file.write('\r' + line.ljust(width))
                self.file.flush()
            elif new_step or self.said == self.start or time.monotonic() - self.said >= SILENCE:
                what = self._text() if new_step or self.last is None else 'still working after ' + self._text()
                self.file.write('anisotropic_fairing: %s (%d steps in all, %.1f s)\n' % (what, self.steps, elapsed))
                self.file.flush()
                self.said = time.monotonic()
        except Exception:   # stderr closed or gone, or tqdm failing: the run goes on without a display
            self.file = self.bar = None

    def _open(self):
        try:
            from tqdm import tqdm
        except ImportError:
            tqdm = None
        if tqdm is not None:
            # delay: not shown before the refresh below; started when the run did, not when the display did
            self.bar = tqdm(desc='anisotropic_fairing', unit=' steps', file=self.file, leave=True, dynamic_ncols=True,
                            mininterval=0, delay=1e-9)
            self.bar.start_t -= time.monotonic() - self.start
            return
        try:
            self.terminal = bool(self.file.isatty())
        except (AttributeError, ValueError):
            self.terminal = False

    def _close(self, end):
        try:
            if self.bar is not None:
                self.bar.n = self.steps
                self.bar.set_postfix_str(end + ' after ' + self._text(), refresh=False)
                self.bar.close()
            elif self.file is not None:
                seconds = time.monotonic() - self.start
                line = 'anisotropic_fairing: %s after %d steps, %.1f s' % (end, self.steps, seconds)
                self.file.write(('\r' + line.ljust(self.width) if self.terminal else line) + '\n')
                self.file.flush()
        except Exception:
            pass
