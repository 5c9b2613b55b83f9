"""The text progress line of ``progress=True``."""

import sys


class TextProgress:
    """Print one line per batch on stderr, rewritten in place."""

    def __init__(self, stream=None):
        self.stream = stream if stream is not None else sys.stderr

    def __call__(self, event):
        kind = event.get("event")
        if kind not in ("started", "batch", "finished"):
            return
        where = f"[α = {event['alpha']:g}, point {event['point'] + 1}/{event['points']}]"
        if kind == "batch":
            line = f"{where} {event['ics_done']}/{event['ics_max']} ICs"
            mean, sem = event.get("mean"), event.get("sem")
            if mean is not None and sem == sem and sem is not None:
                line += f"  λ = {mean:.4f} ± {sem:.4f}"
            line += f"  {event['elapsed_s']:.1f} s"
            self.stream.write("\r" + line.ljust(72))
        elif kind == "finished":
            line = (
                f"{where} done: λ = {event['mean']:.4f} ± {event['sem']:.4f}"
                f" over {event['ics_done']} ICs, {event['elapsed_s']:.1f} s"
            )
            self.stream.write("\r" + line.ljust(72) + "\n")
        self.stream.flush()
