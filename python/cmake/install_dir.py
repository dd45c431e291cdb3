"""Prints where a package goes under an install prefix: sysconfig's 'platlib' for the prefix.

Used by python/CMakeLists.txt (argument: the install prefix). Debian's default scheme
('posix_local') appends /local to its base, so /usr/local is passed as base /usr; on Debian,
the prefix /usr takes the system scheme (/usr/lib/python3/dist-packages) and any other
prefix the plain posix one (<prefix>/lib/pythonX.Y/site-packages).
"""
import os
import sys
import sysconfig

prefix = os.path.normpath(sys.argv[1])
get_scheme = getattr(sysconfig, "get_default_scheme", None)
scheme = get_scheme() if get_scheme else "posix_prefix"
base = prefix
if scheme == "posix_local":
    if prefix.endswith("/local"):
        base = os.path.dirname(prefix)
    elif prefix == "/usr" and "deb_system" in sysconfig.get_scheme_names():
        scheme = "deb_system"
    else:
        scheme = "posix_prefix"
print(sysconfig.get_path("platlib", scheme, vars={"base": base, "platbase": base}))
