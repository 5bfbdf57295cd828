"""Reads a hairsketch motion .usda (and the static .usda of the same session) with usd-core.

usage: check_motion.py MOTION.usda STATIC.usda

Prints ONE JSON line: the stage's start and end time codes and time codes per second, the time
samples of /hairsketch/groom/hair's points and of /hairsketch/head's transform (when there is
a head), whether the hair's points at the first time sample equal the static file's points, and
the largest move of any point between the first and the last sample (stage units).
"""

import json
import sys

from pxr import Usd, UsdGeom


def main():
    motion = Usd.Stage.Open(sys.argv[1])
    static = Usd.Stage.Open(sys.argv[2])
    hair = UsdGeom.BasisCurves(motion.GetPrimAtPath("/hairsketch/groom/hair"))
    points = hair.GetPointsAttr()
    samples = points.GetTimeSamples()
    still = UsdGeom.BasisCurves(static.GetPrimAtPath("/hairsketch/groom/hair")).GetPointsAttr().Get()
    first = points.Get(samples[0]) if samples else None
    last = points.Get(samples[-1]) if samples else None
    moved = 0.0
    if first is not None and last is not None:
        for a, b in zip(first, last):
            moved = max(moved, max(abs(a[i] - b[i]) for i in range(3)))
    head = motion.GetPrimAtPath("/hairsketch/head")
    head_samples = []
    if head:
        ops = UsdGeom.Xformable(head).GetOrderedXformOps()
        head_samples = ops[0].GetAttr().GetTimeSamples() if ops else []
    guides = UsdGeom.BasisCurves(motion.GetPrimAtPath("/hairsketch/groom/guides"))
    print(
        json.dumps(
            {
                "start": motion.GetStartTimeCode(),
                "end": motion.GetEndTimeCode(),
                "perSecond": motion.GetTimeCodesPerSecond(),
                "hairSamples": list(samples),
                "guideSamples": list(guides.GetPointsAttr().GetTimeSamples()),
                "headSamples": list(head_samples),
                "firstEqualsStatic": first is not None and list(first) == list(still),
                "defaultEqualsStatic": list(points.Get()) == list(still),
                "points": len(still),
                "moved": moved,
            }
        )
    )


if __name__ == "__main__":
    main()
