"""The teacher's own checks: each function gets the run and returns the share of the points
(0 to 1, a bool, or a (share, message) pair)."""


def smooth(run):
    """Full points for a run that moved at least a metre and never faster than 0.8 m/s."""
    travelled = sum(
        ((x1 - x0) ** 2 + (y1 - y0) ** 2) ** 0.5
        for x0, y0, x1, y1 in zip(run["x"], run["y"], run["x"][1:], run["y"][1:])
    )
    fastest = max(run["speed"], default=0.0)
    if travelled < 1.0:
        return 0.0, f"moved {travelled:.2f} m"
    if fastest > 0.8:
        return 0.5, f"up to {fastest:.2f} m/s"
    return 1.0, f"{travelled:.2f} m, at most {fastest:.2f} m/s"
