"""Writing figure files the way granshock writes every output (docs/output_format.md,
"The run directory"): into a real directory only, never through a symbolic link, and
whole or not at all. The directory is opened once without following a link; each figure
is drawn into NAME.tmp, created new in it (O_EXCL | O_NOFOLLOW: a link or a file planted
under that name is never written through, and a stale temporary that is a regular file is
removed first), then renamed over NAME, which replaces a link there instead of writing
where it points. Used by plot_fields.py and plot_detachment.py, installed beside them.
"""
import os
import stat


class FigureDirectory:
    """A directory of figures, opened without following a link (created when absent)."""

    def __init__(self, path):
        try:
            os.mkdir(path)
        except FileExistsError:
            pass
        try:
            self.fd = os.open(path, os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW | os.O_CLOEXEC)
        except OSError as e:
            raise SystemExit(f"{path}: not a directory of its own ({e.strerror}); figures are "
                             "written only into a real directory, not through a link")
        self.path = path

    def save(self, fig, name, **savefig_options):
        """fig.savefig into NAME in this directory, through a temporary of its own."""
        tmp = name + ".tmp"
        try:
            st = os.stat(tmp, dir_fd=self.fd, follow_symlinks=False)
        except FileNotFoundError:
            st = None
        if st is not None:
            if not stat.S_ISREG(st.st_mode):
                raise SystemExit(f"{os.path.join(self.path, tmp)} is not a regular file; granshock "
                                 "writes only files it creates itself: remove it")
            os.unlink(tmp, dir_fd=self.fd)  # a stale temporary of a killed run
        fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC,
                     0o644, dir_fd=self.fd)
        try:
            with os.fdopen(fd, "wb") as f:
                fig.savefig(f, format=os.path.splitext(name)[1][1:], **savefig_options)
            os.replace(tmp, name, src_dir_fd=self.fd, dst_dir_fd=self.fd)
        except BaseException:
            try:
                os.unlink(tmp, dir_fd=self.fd)
            except OSError:
                pass
            raise

    def close(self):
        os.close(self.fd)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
