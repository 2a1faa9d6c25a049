#!/usr/bin/env python3
"""Edits one elite of a repertoire's archive.json the way anyone could: its distance (and
fitness) raised by 0.5 and the file's checksum recomputed (FNV-1a 64 over the compact, sorted
JSON without it), so only a replay of the elite can tell. Used by the tests of `repertoire
--resume` and `adapt`, which must refuse such an archive.

Every other number keeps the text hexgait wrote: nlohmann's shortest-digits printing and
Python's differ for some doubles (17 digits against 16), and the checksum is over that text.

Usage: edit_archive_elite.py ARCHIVE_JSON
"""
import json
import sys


class Number(str):
    """A number as the text it was read from."""


def dump(value):
    """Compact JSON with sorted keys, numbers as read: what hexgait's checksum covers."""
    if isinstance(value, dict):
        return "{" + ",".join(json.dumps(k, ensure_ascii=False) + ":" + dump(value[k])
                              for k in sorted(value)) + "}"
    if isinstance(value, list):
        return "[" + ",".join(dump(v) for v in value) + "]"
    if isinstance(value, Number):
        return str(value)
    return json.dumps(value, ensure_ascii=False)


path = sys.argv[1]
archive = json.load(open(path), parse_float=Number, parse_int=Number)
elite = archive["elites"][len(archive["elites"]) // 2]
# Three decimals: printed alike by Python and nlohmann.
elite["result"]["distance"] = Number(repr(round(float(elite["result"]["distance"]) + 0.5, 3)))
elite["fitness"] = elite["result"]["distance"]
archive.pop("checksum")
h = 0xCBF29CE484222325
for byte in dump(archive).encode():
    h = ((h ^ byte) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
archive["checksum"] = format(h, "016x")
open(path, "w").write(dump(archive) + "\n")
