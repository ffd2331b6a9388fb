"""dmdvox: predict what a DED toolpath builds, before anything is deposited.

Command-line entry point, kept thin: argument parsing, dispatch, and the mapping of errors to
exit codes (0 ok, 2 bad input or refused request, 1 internal error). With --json exactly one
JSON object goes to stdout; logs and warnings go to stderr.
"""

from __future__ import annotations

import argparse
import json
import sys
import traceback

from .errors import DmdvoxError


def _add_gcode_options(p: argparse.ArgumentParser) -> None:
    from .toolpath.dialects import DIALECT_NAMES

    p.add_argument("gcode", help="G-code file")
    p.add_argument("--dialect", default="auto", choices=DIALECT_NAMES,
                   help="deposition rules (default auto: E words mean reprap, else M-code families)")
    p.add_argument("--laser-on", help="custom dialect: comma list of codes that start deposition, e.g. 'M65,M101'")
    p.add_argument("--laser-off", help="custom dialect: comma list of codes that stop deposition")
    p.add_argument("--strict", action="store_true", help="stop at the first malformed line (exit 2)")
    p.add_argument("--json", action="store_true", help="print one JSON object on stdout")


def _read(args):
    from .toolpath import read_gcode

    return read_gcode(args.gcode, dialect=args.dialect, strict=args.strict,
                      laser_on=args.laser_on, laser_off=args.laser_off)


def cmd_info(args) -> dict:
    from .toolpath.summary import format_summary, summarize

    tp = _read(args)
    info = summarize(tp)
    for warning in info["warnings"]:
        print(f"warning: {warning}", file=sys.stderr)
    if not args.json:
        print(format_summary(tp, info))
    return info


def build_parser() -> argparse.ArgumentParser:
    from . import __version__

    parser = argparse.ArgumentParser(prog="dmdvox", description=__doc__.split("\n")[0])
    parser.add_argument("--version", action="version", version=f"dmdvox {__version__}")
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    p = sub.add_parser("info", help="summarise a G-code program (moves, lengths, layers, time)")
    _add_gcode_options(p)
    p.set_defaults(handler=cmd_info)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    want_json = getattr(args, "json", False)
    try:
        result = args.handler(args)
    except DmdvoxError as exc:
        print(f"dmdvox: error: {exc}", file=sys.stderr)
        if want_json:
            print(json.dumps({"error": str(exc), "exit_code": exc.exit_code}))
        return exc.exit_code
    except KeyboardInterrupt:
        print("dmdvox: interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # an internal error: keep the traceback for the bug report
        traceback.print_exc(file=sys.stderr)
        if want_json:
            print(json.dumps({"error": f"internal error: {exc}", "exit_code": 1}))
        return 1
    if want_json:
        print(json.dumps(result, allow_nan=False))
    return 0


if __name__ == "__main__":
    sys.exit(main())
