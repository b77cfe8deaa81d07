"""The project's error for bad input: a ValueError that says where the input came from."""


class InputError(ValueError):
    """Bad input, with its source: ``InputError("stock.json:12: z_top must be a number")``."""
