"""The server runs without torch: no package the server loads imports it (torch is for
training, under models/)."""

import subprocess
import sys


def test_the_server_packages_do_not_import_torch():
    code = (
        "import sys, importlib, pkgutil\n"
        "import interplay\n"
        "for pkg in (interplay,):\n"
        "    for m in pkgutil.walk_packages(pkg.__path__, pkg.__name__ + '.'):\n"
        "        importlib.import_module(m.name)\n"
        "bad = [m for m in sys.modules if m == 'torch' or m.startswith('torch.')]\n"
        "print(bad); sys.exit(1 if bad else 0)\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert out.returncode == 0, out.stdout + out.stderr
