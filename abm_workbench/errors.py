"""The project's error for bad input: a ValueError that says where the input came from."""


class InputError(ValueError):
    """Bad input, with its source: ``InputError("stock.json:12: z_top must be a number")``."""


class CLPointError(ValueError):
    """A bad value at one CL point of a toolpath: its 0-based `index` and what is wrong (`detail`)."""

    def __init__(self, index, detail):
        super().__init__(f"CL {index}: {detail}")
        self.index, self.detail = int(index), detail


class ParameterError(InputError):
    """A bad value of one job parameter: its `field` (a name of ``jobs.parameters.PARAMETERS``),
    what is wrong (`detail`, plain words without the field's name) and, when the value came from a
    file, that file (`where`). Each front end words it its own way: ``--diameter: ...`` on the
    command line, the field marked and its label in the GUI; ``str()`` is the neutral form."""

    def __init__(self, field, detail, where=None):
        super().__init__(f"{where}: {field}: {detail}" if where else f"{field}: {detail}")
        self.field, self.detail, self.where = field, detail, where


class MissingParameter(ParameterError):
    """A required job parameter that no source gives."""

    def __init__(self, field):
        super().__init__(field, "is required and given nowhere")


def note(text):
    """`text` unchanged: a message said to the user that no exception carries (a warning's words, a value
    that is a phrase), marked so that the GUI's translation template holds it (gui.messages gathers it)."""
    return text
