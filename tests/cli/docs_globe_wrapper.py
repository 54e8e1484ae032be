#!/usr/bin/env python3
"""`globe` for the docs-commands test (docs_commands_test.py): runs $GLOBE_REAL with the documented
arguments, made small where they only set how much work is done — frame sizes, path rates, movie
frame rates, timed frames per configuration, viewer frames — so every documented command runs in
seconds. What a command does (its subcommand, planet, path, camera, quality, outputs) is unchanged.
The viewer runs under xvfb-run when there is no display.
"""
import os
import sys

SMALL = {
    "render": {"--size": "160x90"},
    "bench": {"--size": "160x90", "--rate": "2"},
    # Two configurations at one camera: a full sweep converges configurations of 3 M triangles.
    "trade": {"--size": "160x90", "--frames": "1", "--stride": "8", "--configs": "2", "--cameras": "1km"},
    "view": {"--size": "160x90", "--frames": "5"},
    "physics": {"--seconds": "0.5"},
}


def set_option(args, name, value):
    """Replaces NAME's value (`--name V` or `--name=V`), or appends it."""
    for k, arg in enumerate(args):
        if arg == name and k + 1 < len(args):
            args[k + 1] = value
            return
        if arg.startswith(name + "="):
            args[k] = f"{name}={value}"
            return
    args += [name, value]


def option(args, name):
    for k, arg in enumerate(args):
        if arg == name and k + 1 < len(args):
            return args[k + 1]
        if arg.startswith(name + "="):
            return arg[len(name) + 1:]
    return None


def main():
    real = os.environ["GLOBE_REAL"]
    args = sys.argv[1:]
    command = args[0] if args else ""
    for name, value in SMALL.get(command, {}).items():
        set_option(args, name, value)
    if command == "movie":
        set_option(args, "--size", "64x36")
        set_option(args, "--fps", "24" if (option(args, "--out") or "").endswith(".mp4") else "2")
    argv = [real] + args
    if command == "view" and not os.environ.get("DISPLAY"):
        argv = ["xvfb-run", "-a", "-s", "-screen 0 1024x768x24"] + argv
    os.execvp(argv[0], argv)


if __name__ == "__main__":
    main()
