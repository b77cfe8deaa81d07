"""The project's error for bad input: a ValueError that says where the input came from."""


class InputError(ValueError):
    """Bad input, with its source: ``InputError("stock.json:12: z_top must be a number")``."""


class CLPointError(ValueError):
    """A bad value at one CL point of a toolpath: its 0-based `index` and what is wrong (`detail`)."""

    def __init__(self, index, detail):
        super().__init__(f"CL {index}: {detail}")
        self.index, self.detail = int(index), detail
