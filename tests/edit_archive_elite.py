#!/usr/bin/env python3
"""Edits one elite of a repertoire's archive.json the way anyone could: its distance (and
fitness) raised by 0.5 and the file's checksum recomputed (FNV-1a 64 over the compact, sorted
JSON without it), so only a replay of the elite can tell. Used by the tests of `repertoire
--resume` and `adapt`, which must refuse such an archive.

Usage: edit_archive_elite.py ARCHIVE_JSON
"""
import json
import sys

path = sys.argv[1]
archive = json.load(open(path))
elite = archive["elites"][len(archive["elites"]) // 2]
elite["result"]["distance"] += 0.5
elite["fitness"] = elite["result"]["distance"]
archive.pop("checksum")
body = json.dumps(archive, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
h = 0xCBF29CE484222325
for byte in body.encode():
    h = ((h ^ byte) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
archive["checksum"] = format(h, "016x")
json.dump(archive, open(path, "w"), indent=1)
