"""The `ragnav` console script: thin argument parsing around the package's stage functions.

Each stage module exposes `register(subparsers, common)`; user errors and OS errors (a file where a
folder should be, a read-only folder, a full disk) print one line naming the path and exit 2.
"""

from __future__ import annotations

import argparse
import importlib
import os
import sys
from pathlib import Path

from ragnav_jax.errors import UserError, os_error_message, printable

# Stage modules that add subcommands; later stages append theirs.
COMMAND_MODULES = ("ragnav_jax.world.commands", "ragnav_jax.sim.commands", "ragnav_jax.language.commands", "ragnav_jax.memory.commands", "ragnav_jax.retrieval.commands", "ragnav_jax.planning.commands", "ragnav_jax.evaluation.commands", "ragnav_jax.bench.commands", "ragnav_jax.evaluation.eval_commands", "ragnav_jax.doctor")


def _common_parser() -> argparse.ArgumentParser:
    common = argparse.ArgumentParser(add_help=False)
    common.add_argument("--config", help="YAML config (default: built-in defaults, see configs/default.yaml)")
    common.add_argument("--quiet", action="store_true", help="no progress bars")
    common.add_argument("overrides", nargs="*", default=[], metavar="KEY=VALUE", help="dotted config overrides")
    return common


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # argparse's own exit code is already 2; one line, like every other user error
        self.exit(2, f"ragnav: error: {printable(message)} (see {self.prog} --help)\n")


class PositionalsAndOverrides(argparse.Action):
    """Sorts a command's positionals into its own values and KEY=VALUE config overrides (any order).

    The common parser's `overrides` positional comes first and takes all items but those of the command's
    last positional; this action, given to that positional, sorts them all again: an item with '=' that is
    not an existing path is an override, the rest are this positional's values."""

    def __call__(self, parser, namespace, values, option_string=None):
        items = [*(getattr(namespace, "overrides", None) or []), *([values] if isinstance(values, str) else values)]
        override = [("=" in x and not Path(x).exists()) for x in items]
        namespace.overrides = [x for x, o in zip(items, override) if o]
        mine = [x for x, o in zip(items, override) if not o]
        if not mine:
            parser.error(f"the following arguments are required: {self.metavar or self.dest}")
        if self.nargs is None and len(mine) > 1:
            parser.error(f"one {self.metavar or self.dest} expected, got {' '.join(mine)}")
        setattr(namespace, self.dest, mine if self.nargs is not None else mine[0])


def build_parser() -> argparse.ArgumentParser:
    parser = _Parser(prog="ragnav", description="RAGNav in JAX: scenes, memory, retrieval, planning, evaluation")
    from ragnav_jax import __version__

    parser.add_argument("--version", action="version", version=f"ragnav-jax {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    common = _common_parser()
    for name in COMMAND_MODULES:
        importlib.import_module(name).register(sub, common)
    return parser


def _split_overrides(args) -> None:
    """Positional KEY=VALUE items are overrides; anything else is a usage error."""
    items = getattr(args, "overrides", []) or []
    bad = [x for x in items if "=" not in x]
    if bad:
        raise UserError(f"unexpected argument(s) {' '.join(bad)}: overrides must look like key.sub=value")
    if items and getattr(args, "overrides_allowed", True) is False:
        raise UserError(f"'{args.command}' takes no config overrides (got {' '.join(items)})")


def main(argv: list[str] | None = None) -> int:
    from ragnav_jax.config import load_config
    from ragnav_jax.runs import discard_failed_runs

    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        _split_overrides(args)
        cfg = load_config(args.config, args.overrides)
        if os.environ.get("RAGNAV_DISTRIBUTED"):  # several hosts: one process per host (evaluation/sharding.py)
            from ragnav_jax.evaluation.sharding import init_distributed

            init_distributed()
        with discard_failed_runs():
            return int(args.func(args, cfg) or 0)
    except UserError as e:
        print(f"ragnav: error: {printable(e)}", file=sys.stderr)
        return e.exit_code
    except KeyboardInterrupt:
        print("ragnav: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 0
    except OSError as e:  # read-only folder, full disk, a file where a folder should be: the path and the reason
        print(f"ragnav: error: {printable(os_error_message(e))}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
