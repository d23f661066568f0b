"""The output folder of the commands (simulate, tradeoff) and the exit codes they share.

The folder is checked before the run (not after it), and written all at once after it: the files go
to a temporary folder, made next to the target (in its parent) and renamed to the target when every
file is written; when the target folder exists, the temporary folder is made inside it and each file is
then renamed into place, replacing the file of the same name whole. A run that cannot write (a full
disk, no permission) leaves nothing behind: no half-written file, no partial folder, not even the
parent folders it made. Files of the command's already in the folder, and symbolic links in the place
of one, are refused by name unless --force: with it they are replaced (a link itself, never the file
it points to), and the command's files the run does not write (an earlier run's plot, say) are
removed, so that the folder holds one run.
"""

from __future__ import annotations

import errno
import os
import shutil
import tempfile
from collections.abc import Callable, Sequence
from pathlib import Path

__all__ = ["EXIT_BAD_INPUT", "EXIT_CODES_HELP", "EXIT_DIVERGED", "EXIT_EXISTS", "EXIT_INTERRUPTED", "EXIT_OK",
           "EXIT_UNWRITABLE", "OutFolder", "OutputError", "OutputExists"]

# the exit codes of `simulate` and `tradeoff`
EXIT_OK = 0
EXIT_DIVERGED = 1  # simulate: the state became non-finite (the records up to there are written)
EXIT_BAD_INPUT = 2  # a bad argument or input file (nothing run, nothing written)
EXIT_UNWRITABLE = 3  # the outputs could not be written (a full disk, no permission): nothing written
EXIT_EXISTS = 4  # --out holds the command's files or a link in their place, and no --force: nothing run
EXIT_INTERRUPTED = 130  # Ctrl-C: nothing written
EXIT_CODES_HELP = (f"exit codes: {EXIT_OK} done; {EXIT_DIVERGED} the state became non-finite (simulate; the "
                   f"records up to there are written); {EXIT_BAD_INPUT} bad input (an argument, a file, or a "
                   f"warning turned into an error by python -W error); {EXIT_UNWRITABLE} the outputs could not be "
                   f"written (nothing written); {EXIT_EXISTS} --out holds files of an earlier run or a symbolic "
                   f"link in their place (use --force to replace them); {EXIT_INTERRUPTED} interrupted (Ctrl-C)")

_PARTIAL = ".rigiddyn-partial-"  # prefix of the temporary folder next to the target


class OutputExists(Exception):
    """--out holds one of the command's files, or a symbolic link in its place, and --force was not given."""


class OutputError(Exception):
    """The outputs could not be written (the message names the file and the reason); nothing was written."""


def _reason(error: OSError) -> str:
    return error.strerror or str(error)


class OutFolder:
    """The folder `out` for the files `outputs` (those of the run; `known`: every file the command may
    write, default `outputs`), checked at construction: ValueError "--out: expected ..., got ..."
    (a file, a broken symbolic link, a path the system refuses, e.g. too long, a folder in the way of
    an output, not writable), OutputExists (one of `known`, or a symbolic link in its place, is
    there and not `force`). Nothing is created until `write`."""

    def __init__(self, out: str, outputs: Sequence[str], force: bool = False, known: Sequence[str] = ()) -> None:
        self.path = Path(out)
        self.outputs = list(outputs)
        self.known = list(dict.fromkeys([*self.outputs, *known]))
        self.force = force
        shown = repr(out) if len(out) <= 80 else f"a path of {len(out)} characters, {out[:30]!r}..."
        expected = f"--out: expected a folder where {', '.join(self.outputs)} can be written, got {shown}"
        try:
            self._check(expected)
        except OSError as error:  # a path the system refuses (too long, too many links, ...)
            raise ValueError(f"{expected} ({_reason(error)})") from None

    def _check(self, expected: str) -> None:
        folder = self.path
        if folder.is_symlink() and not folder.exists():
            raise ValueError(f"{expected} (a broken symbolic link)")
        if folder.exists() and not folder.is_dir():
            raise ValueError(f"{expected} (a file)")
        if folder.is_dir():
            taken = [name for name in self.outputs if (folder / name).is_dir() and not (folder / name).is_symlink()]
            if taken:
                raise ValueError(f"{expected} (it holds a folder named {taken[0]})")
            self.existing()
            writable = folder
        else:
            writable = self._existing_ancestor(expected)
        try:
            with tempfile.TemporaryFile(dir=writable):
                pass
        except OSError as error:
            raise ValueError(f"{expected} (not writable: {_reason(error)})") from None

    def _existing_ancestor(self, expected: str) -> Path:
        """The nearest folder above the missing target (ValueError if a file is in the way)."""
        for parent in self.path.absolute().parents:
            if parent.exists():
                if not parent.is_dir():
                    raise ValueError(f"{expected} (below the file {str(parent)!r})")
                return parent
        raise ValueError(f"{expected} (no folder above it exists)")  # pragma: no cover - the root exists

    def existing(self) -> None:
        """OutputExists naming the first of the command's files already in the folder (a symbolic link
        in the place of one named as such), unless force."""
        if self.force or not self.path.is_dir():
            return
        for name in self.known:
            target = self.path / name
            if target.is_symlink():
                raise OutputExists(f"--out: {str(target)!r} is a symbolic link (to {os.readlink(target)!r}): refusing "
                                   "to write through it; --force replaces the link itself")
            if target.exists():
                raise OutputExists(f"--out: {str(target)!r} exists (from an earlier run): refusing to overwrite it; "
                                   "--force replaces it")

    def write(self, write_files: Callable[[Path], Sequence[Path]]) -> list[Path]:
        """`write_files(folder)` writes the outputs into a temporary folder and returns the paths written;
        they are then moved to the target. Returns their final paths. The temporary folder is made in the
        target's parent when the target is missing (then renamed to it), else inside the target (each file
        then renamed into place: the same file system, each file replaced whole). OutputError (naming the
        final path and the reason) if writing fails, OutputExists if one of the command's files appeared
        meanwhile (without force): nothing is left behind, as for any other exception."""
        made: list[Path] = []
        partial: Path | None = None
        try:
            fresh = not self.path.is_dir()
            if fresh:
                self._make_parents(made)
            partial = Path(tempfile.mkdtemp(prefix=_PARTIAL, dir=self.path.absolute().parent if fresh else self.path))
            try:
                written = [Path(p) for p in write_files(partial)]
            except OSError as error:
                raise OutputError(self._failure(error, partial)) from None
            names = [p.relative_to(partial) for p in written]
            self._commit(partial, names, fresh)
            partial = None
            return [self.path / name for name in names]
        except OSError as error:  # making the temporary folder
            raise OutputError(f"cannot write to {str(self.path)!r}: {_reason(error)}; nothing written") from None
        finally:
            if partial is not None:  # not committed
                shutil.rmtree(partial, ignore_errors=True)
                for folder in reversed(made):
                    try:
                        folder.rmdir()
                    except OSError:
                        break

    def _make_parents(self, made: list[Path]) -> None:
        """Create the missing folders above the target, outermost first, each appended to `made`."""
        for folder in reversed(self.path.absolute().parents):
            if not folder.exists():
                folder.mkdir()
                made.append(folder)

    def _failure(self, error: OSError, partial: Path) -> str:
        """The message of a failed write, naming the final path of the file (not the temporary one)."""
        where = str(self.path)
        if error.filename is not None:
            name = Path(os.fsdecode(error.filename))
            where = str(self.path / name.relative_to(partial)) if name.is_relative_to(partial) else str(name)
        full = " (the disk is full)" if error.errno in (errno.ENOSPC, errno.EDQUOT) else ""
        return f"cannot write {where!r}: {_reason(error)}{full}; nothing written"

    def _commit(self, partial: Path, names: Sequence[Path], fresh: bool) -> None:
        """Move the written files from `partial` to the target: one rename of the folder when the target was
        missing, else one rename per file, after checking for files that appeared during the run; with
        force, the command's files that the run did not write are removed."""
        try:
            if fresh:
                partial.rename(self.path)
                return
            self.existing()
            for name in names:
                os.replace(partial / name, self.path / name)
            for stale in [n for n in self.known if Path(n) not in names]:
                target = self.path / stale
                if target.is_symlink() or target.is_file():
                    target.unlink()
            partial.rmdir()
        except OSError as error:
            raise OutputError(f"cannot move the files into {str(self.path)!r}: {_reason(error)}") from None
