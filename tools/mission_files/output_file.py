"""Writing a file the user names (summary.json, the picture's SVG and PNG) by the rule every C++
program follows (include/base/output_file.hpp), so that no tool replaces a device, a FIFO or a
link with a regular file:

- a regular file, or nothing yet: the bytes go to a new temporary file in the same folder
  (`<FILE>.tmp.<pid>.<n>`), flushed to disk and renamed over FILE, so a reader sees the old file
  or the whole new one; on failure the temporary is removed and FILE stays as it was. A file
  that existed keeps its permission bits; a new one gets 0666 minus the umask;
- a symbolic link: followed (a chain too, a relative target taken from the link's folder) and
  the rule applied to the path it leads to; the link stays a link;
- a character device (/dev/null, /dev/full) or a FIFO: written through, never created,
  truncated, renamed over or removed. A FIFO is opened non-blocking and waits up to
  FIFO_READER_WAIT_S for a reader, then fails ("no process is reading the FIFO"): never a hang;
- a directory, a block device, a socket: refused.

Every problem raises OutputFileError (an OSError) whose text names the path:
"cannot write '/dev/full': No space left on device". Python 3 standard library only.
"""

import errno
import os
import stat
import time

FIFO_READER_WAIT_S = 5.0
MAX_LINKS = 40  # Linux's own limit for a path
MAX_TEMPORARY_NAMES = 100
FIFO_POLL_S = 0.01


class OutputFileError(OSError):
    """A user-named output that could not be written; str() is the whole message."""

    def __init__(self, path, target, reason):
        where = "'%s'" % path if target == path else "'%s' (a link to '%s')" % (path, target)
        super().__init__("cannot write %s: %s" % (where, reason))


def follow_links(path):
    """The path `path` leads to once every symbolic link at its end is followed."""
    at = path
    for _ in range(MAX_LINKS + 1):
        if not os.path.islink(at):
            return at
        link = os.readlink(at)
        at = link if os.path.isabs(link) else os.path.join(os.path.dirname(at) or ".", link)
    raise OSError(errno.ELOOP, os.strerror(errno.ELOOP))


def refusal(mode):
    """Why a file of this kind is not written, or None when the rule writes it."""
    if stat.S_ISREG(mode) or stat.S_ISCHR(mode) or stat.S_ISFIFO(mode):
        return None
    if stat.S_ISDIR(mode):
        return "it is a directory"
    if stat.S_ISBLK(mode):
        return "it is a block device"
    if stat.S_ISSOCK(mode):
        return "it is a socket"
    return "it is not a file that can be written"


def write_all(fd, data):
    view = memoryview(data)
    while view:
        view = view[os.write(fd, view):]


def create_temporary(target):
    """(descriptor, name) of a new file beside `target`."""
    for n in range(MAX_TEMPORARY_NAMES):
        name = "%s.tmp.%d.%d" % (target, os.getpid(), n)
        try:
            return os.open(name, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_CLOEXEC, 0o666), name
        except FileExistsError:
            continue
    raise OSError(errno.EEXIST, os.strerror(errno.EEXIST))


def replace(target, data, old):
    """The temporary file renamed over `target` once flushed to disk; removed on failure."""
    fd, temporary = create_temporary(target)
    try:
        if old is not None:
            os.fchmod(fd, stat.S_IMODE(old.st_mode))  # a replaced file keeps its permissions
        write_all(fd, data)
        os.fsync(fd)
        os.close(fd)
        fd = -1
        os.rename(temporary, target)
    except BaseException:
        if fd >= 0:
            os.close(fd)
        os.unlink(temporary)
        raise


def open_through(target, fifo):
    """A device or FIFO opened for writing without creating or truncating it; a FIFO waits
    (bounded) for its reader."""
    flags = os.O_WRONLY | os.O_NONBLOCK | os.O_NOCTTY | os.O_NOFOLLOW | os.O_CLOEXEC
    give_up = time.monotonic() + (FIFO_READER_WAIT_S if fifo else 0.0)
    while True:
        try:
            return os.open(target, flags)
        except OSError as e:
            if e.errno != errno.ENXIO or not fifo or time.monotonic() >= give_up:
                raise
        time.sleep(FIFO_POLL_S)


def write_through(target, data, fifo):
    try:
        fd = open_through(target, fifo)
    except OSError as e:
        if fifo and e.errno == errno.ENXIO:
            raise OSError(e.errno, "no process is reading the FIFO (waited %d s)"
                          % FIFO_READER_WAIT_S) from e
        raise
    try:
        os.set_blocking(fd, True)  # from now on, writes wait for room
        write_all(fd, data)
    finally:
        os.close(fd)


def write_output_file(path, data):
    """`data` (str, written as UTF-8, or bytes) written to `path` by the rule above."""
    if isinstance(data, str):
        data = data.encode("utf-8")
    path = os.fspath(path)
    target = path
    try:
        target = follow_links(path)
        try:
            old = os.stat(target)
        except FileNotFoundError:
            old = None
        if old is None or stat.S_ISREG(old.st_mode):
            replace(target, data, old)
        elif refusal(old.st_mode):
            raise OSError(errno.EINVAL, refusal(old.st_mode))
        else:
            write_through(target, data, stat.S_ISFIFO(old.st_mode))
    except OSError as e:
        raise OutputFileError(path, target, e.strerror or str(e)) from e
