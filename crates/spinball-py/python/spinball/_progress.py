"""The text progress line of ``progress=True``."""

import sys

from ._spinball import plus_minus


class TextProgress:
    """Progress on stderr: on a terminal one line per point, rewritten in
    place after every batch; into a file or a pipe only the line of each
    finished point (no carriage returns in a log)."""

    def __init__(self, stream=None):
        self.stream = stream if stream is not None else sys.stderr
        isatty = getattr(self.stream, "isatty", None)
        self.terminal = bool(isatty and isatty())

    def __call__(self, event):
        kind = event.get("event")
        if kind not in ("started", "batch", "finished"):
            return
        where = f"[α = {event['alpha']:g}, point {event['point'] + 1}/{event['points']}]"
        if kind == "batch":
            if not self.terminal:
                return
            line = f"{where} {event['ics_done']}/{event['ics_max']} ICs"
            mean, sem = event.get("mean"), event.get("sem")
            if mean is not None and sem is not None and sem == sem:
                line += f"  λ = {plus_minus(mean, sem)}"
            line += f"  {event['elapsed_s']:.1f} s"
            self.stream.write("\r" + line.ljust(72))
        elif kind == "finished":
            line = (
                f"{where} done: λ = {plus_minus(event['mean'], event['sem'])}"
                f" over {event['ics_done']} ICs, {event['elapsed_s']:.1f} s"
            )
            if self.terminal:
                line = "\r" + line.ljust(72)
            self.stream.write(line + "\n")
        else:
            return
        self.stream.flush()
