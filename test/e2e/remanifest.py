#!/usr/bin/env python3
# remanifest.py DIR: rewrites the manifest ("files") of DIR/system.json (docs/FORMATS.md "system/")
# after a test damaged a file on purpose, so that the case reaches the reader's own check of that
# file instead of the manifest's.
import json, os, sys
KNOWN = {"K.mtx", "f.mtx", "dirichlet.mtx", "coordinates.mtx", "K.petsc", "f.petsc", "coordinates.petsc",
         "dirichlet_conditions.json", "provenance.json"}
def fnv(data):
    h = 0xcbf29ce484222325
    for b in data:
        h = ((h ^ b) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return h
d = sys.argv[1]
p = os.path.join(d, "system.json")
j = json.load(open(p))
files = {}
for name in sorted(os.listdir(d)):
    if name in KNOWN:
        data = open(os.path.join(d, name), "rb").read()
        files[name] = {"bytes": len(data), "content": "fnv1a64:%016x" % fnv(data)}
j["files"] = files
open(p, "w").write(json.dumps(j, indent=2) + "\n")
