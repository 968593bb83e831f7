"""A table as a dict of columns, with the values that belong to the whole table in ``attrs``."""


class Columns(dict):
    """Columns by name (numpy arrays, lists of texts), as a dict; ``attrs`` holds the values that
    belong to the whole table, as a pandas DataFrame's ``attrs`` does (what
    ``Screw.sensitivity(frame=False)`` returns: ``attrs["drag_torque_nm"]``,
    ``attrs["variance_nm2"]``)."""

    def __init__(self, columns=(), attrs=None):
        super().__init__(columns)
        self.attrs = dict(attrs or {})

    def __repr__(self):
        return f"Columns({dict.__repr__(self)}, attrs={self.attrs!r})"
