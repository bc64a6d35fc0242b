"""Raw capture read from a named public repository snapshot instead of ../shared/data.

Some sources are too large to copy into ../shared/data (which holds files under 4 MiB in a
few hundred MB). For those the build reads the repository snapshot the search tool's `fetch`
brings to the mirror folder (a bare git directory, `<root>/<owner>+<name>/repo`), at the commit
named in `Snapshot`, so the processed data is reproducible from that snapshot. The app never
reads the mirror at run time: only `interplay data build --staged` does.

The fetch step (once per machine): ask the search tool to `fetch` `github:<owner>/<name>`; it
answers with the git directory's path. A different mirror root can be given by
`INTERPLAY_MIRROR_DIR` or `--mirror`.
"""

from __future__ import annotations

import os
import subprocess
from dataclasses import dataclass
from pathlib import Path

DEFAULT_MIRROR = Path("/work/.mirror")


def mirror_root() -> Path:
    return Path(os.environ.get("INTERPLAY_MIRROR_DIR", str(DEFAULT_MIRROR)))


class SnapshotMissing(RuntimeError):
    """The named snapshot (or its commit) is not on this machine."""


@dataclass(frozen=True)
class Snapshot:
    repo: str       # "owner/name"
    commit: str     # the commit the processed data was built from
    path: str       # the folder inside the repository the build reads
    licence: str    # the licence as the repository states it

    def git_dir(self, root: Path | None = None) -> Path:
        return (root or mirror_root()) / self.repo.replace("/", "+") / "repo"

    def _git(self, root: Path | None, *args: str, text: bool = True) -> subprocess.CompletedProcess:
        return subprocess.run(["git", "--git-dir", str(self.git_dir(root)), *args],
                              capture_output=True, text=text, check=False)

    def require(self, root: Path | None = None) -> Path:
        """The snapshot's git directory; raises SnapshotMissing with the fetch step when it is
        absent or lacks the named commit."""
        gd = self.git_dir(root)
        how = (f"fetch it with the search tool's `fetch github:{self.repo}` (it lands in "
               f"{gd.parent.parent}/{gd.parent.name}/repo), or point INTERPLAY_MIRROR_DIR / --mirror "
               "at a folder holding it")
        if not gd.is_dir():
            raise SnapshotMissing(f"snapshot of {self.repo} not found at {gd}: {how}")
        if self._git(root, "cat-file", "-e", f"{self.commit}^{{commit}}").returncode != 0:
            raise SnapshotMissing(f"snapshot of {self.repo} at {gd} lacks commit {self.commit}: {how}")
        return gd

    def files(self, root: Path | None = None, under: str | None = None) -> list[str]:
        """Paths (repository-relative) of the files under `under` (default: `path`) at the commit."""
        self.require(root)
        out = self._git(root, "ls-tree", "-r", "--name-only", self.commit, "--", under or self.path)
        if out.returncode != 0:
            raise SnapshotMissing(f"{self.repo}@{self.commit}: cannot list {under or self.path}: {out.stderr}")
        return [line for line in out.stdout.splitlines() if line]

    def extract(self, dest: Path, root: Path | None = None, under: str | None = None) -> Path:
        """Write the files under `under` (default: `path`) at the commit into `dest`, keeping
        their repository paths; returns dest / under. Files the snapshot lacks (it leaves out
        files of 4 MiB and more) are skipped and listed in the returned folder's `.absent`."""
        self.require(root)
        under = under or self.path
        listing = self._git(root, "ls-tree", "-r", self.commit, "--", under)
        if listing.returncode != 0:
            raise SnapshotMissing(f"{self.repo}@{self.commit}: cannot list {under}: {listing.stderr}")
        entries = []
        for line in listing.stdout.splitlines():
            head, _, rel = line.partition("\t")
            _, kind, sha = head.split()
            if kind == "blob":
                entries.append((sha, rel))
        proc = subprocess.run(["git", "--git-dir", str(self.git_dir(root)), "cat-file", "--batch"],
                              input="".join(f"{sha}\n" for sha, _ in entries).encode(),
                              capture_output=True, check=False)
        data, pos, absent = proc.stdout, 0, []
        for _sha, rel in entries:
            nl = data.index(b"\n", pos)
            header = data[pos:nl].split()
            pos = nl + 1
            if header[-1] == b"missing":
                absent.append(rel)
                continue
            size = int(header[2])
            target = dest / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(data[pos:pos + size])
            pos += size + 1
        out = dest / under
        out.mkdir(parents=True, exist_ok=True)
        (out / ".absent").write_text("".join(f"{rel}\n" for rel in absent))
        return out


__all__ = ["DEFAULT_MIRROR", "Snapshot", "SnapshotMissing", "mirror_root"]
