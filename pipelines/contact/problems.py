#!/usr/bin/env python3
"""The contact pipeline's problems from the organ's (pipelines/contact/Makefile):
problems.py pressed|pressed-free|spread ORGAN_PROBLEM.json SPREAD_PA > problem.json"""
import json
import sys

kind, organ, spread = sys.argv[1], json.load(open(sys.argv[2])), float(sys.argv[3])
bottom, top = organ["dirichlet"]
if kind in ("pressed", "pressed-free"):
    top["name"] = "pushed top z > 0.025, y < -0.015"
    top["value"] = [None, None, -0.01]
    organ["description"] = "the organ's incision pressed closed from the top" + (", contact on" if kind == "pressed" else ", no contact")
    organ["contact"] = kind == "pressed"
elif kind == "spread":
    organ["dirichlet"] = [bottom]
    organ["cut_loads"] = [{"cut": 0, "pressure": spread}]
    organ["contact"] = True
    organ["description"] = "the organ's incision spread open by a pressure of %g Pa on its faces" % spread
else:
    sys.exit(__doc__)
json.dump(organ, sys.stdout, indent=1)
