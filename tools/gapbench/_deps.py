"""Idempotent dependency check for gapbench (Debian 12: python3-numpy, python3-scipy, python3-yaml).

Imported first by every gapbench script. If a module is missing and we are root, installs the Debian
packages with apt-get (running `apt-get update` once if the first try fails), then re-executes the
script with /usr/bin/python3 (the interpreter those packages install into).
"""
import os
import subprocess
import sys

_PACKAGES = ["python3-numpy", "python3-scipy", "python3-yaml"]


def _have_all():
    try:
        import numpy  # noqa: F401
        import scipy  # noqa: F401
        import scipy.integrate  # noqa: F401
        import scipy.signal  # noqa: F401
        import yaml  # noqa: F401
        return True
    except ImportError:
        return False


def ensure():
    if _have_all():
        return
    if sys.executable != "/usr/bin/python3" and os.path.exists("/usr/bin/python3") \
            and not os.environ.get("GAPBENCH_REEXEC"):
        # The modules may be installed for the system interpreter only (e.g. a pyenv shim is first on PATH).
        os.environ["GAPBENCH_REEXEC"] = "1"
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    if os.geteuid() != 0:
        sys.exit("gapbench needs numpy, scipy and PyYAML: apt-get install -y python3-numpy python3-scipy python3-yaml")
    cmd = ["apt-get", "install", "-y", "-qq"] + _PACKAGES
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    if subprocess.call(cmd, env=env, stdout=subprocess.DEVNULL) != 0:
        subprocess.call(["apt-get", "update", "-qq"], env=env, stdout=subprocess.DEVNULL)
        if subprocess.call(cmd, env=env, stdout=subprocess.DEVNULL) != 0:
            sys.exit("gapbench: could not install " + " ".join(_PACKAGES))
    os.environ["GAPBENCH_REEXEC"] = "1"
    os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)


ensure()
