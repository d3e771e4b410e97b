#!/usr/bin/env python3
"""Writes the page of `mbc run --html` with three.js inside: the template
(toolpath.html) with the page's script (toolpath.js) and three.js and its
OrbitControls (from the npm package pinned in package-lock.json) as data:
URLs of an import map, so that the page needs no network and no other file.
@TITLE@ and @TOOLPATH@ are left for mbc to fill in. Without three.js (npm
could not fetch it: fetch_three.cmake) the page is empty, and mbc's --html
says why.
Usage: make_page.py TEMPLATE SCRIPT THREE_MODULE ORBIT_CONTROLS OUTPUT"""
import base64
import os
import sys


def main():
    template, script, three, orbit, output = sys.argv[1:6]

    def read(path):
        with open(path, "rb") as f:
            return f.read()

    if not (os.path.isfile(three) and os.path.isfile(orbit)):
        with open(output, "w"):
            pass
        return
    page = read(template).decode()
    page = page.replace("@THREE@", base64.b64encode(read(three)).decode())
    page = page.replace("@ORBIT_CONTROLS@",
                        base64.b64encode(read(orbit)).decode())
    page = page.replace("@PAGE_SCRIPT@", read(script).decode())
    for marker in ("@TITLE@", "@TOOLPATH@"):
        if page.count(marker) != 1:
            sys.exit(f"make_page.py: {template} must hold {marker} once")
    with open(output + ".tmp", "w") as f:
        f.write(page)
    os.replace(output + ".tmp", output)


if __name__ == "__main__":
    main()
