#!/usr/bin/env python3
"""The runtime's rooms at the level of symbols: no object of a room uses a
symbol that only a room above it defines. The include paths keep a room
from seeing a higher room's headers; a declaration in a low header of a
function defined higher up (a call running back up) passes them, and this
finds it.

    runtime_layers.py ROOM=OBJECT_LIST ... (lowest room first; each list of
    object files separated by ';', as CMake's $<TARGET_OBJECTS> gives it)
"""
import subprocess
import sys


def symbols(obj, flag):
    out = subprocess.run(["nm", "-C", flag, obj], check=True,
                         capture_output=True, text=True).stdout
    names = set()
    for line in out.splitlines():
        # "  U name" or "address T name"; a demangled name has spaces.
        if flag == "--undefined-only":
            kind, _, name = line.strip().partition(" ")
            if kind == "U":
                names.add(name)
        else:
            parts = line.split(maxsplit=2)
            if len(parts) == 3 and parts[1] in "TWDBRV":
                names.add(parts[2])
    return names


def main():
    rooms = []
    for arg in sys.argv[1:]:
        room, objects = arg.split("=", 1)
        rooms.append((room, [o for o in objects.split(";") if o]))
    home = {}
    for level, (room, objects) in enumerate(rooms):
        for obj in objects:
            for name in symbols(obj, "--defined-only"):
                home.setdefault(name, level)
    failures = 0
    for level, (room, objects) in enumerate(rooms):
        for obj in objects:
            for name in sorted(symbols(obj, "--undefined-only")):
                above = home.get(name)
                if above is not None and above > level:
                    print(f"runtime/src/{room}: {obj.rsplit('/', 1)[-1]} uses "
                          f"{name}, defined in {rooms[above][0]}/ above it")
                    failures += 1
    if not any(objects for _, objects in rooms):
        print("runtime_layers: no objects given")
        return 2
    print(f"runtime_layers: {len(rooms)} rooms, {failures} calls running up")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
