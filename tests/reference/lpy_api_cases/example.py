"""The form of a case file: each case builds what it needs and returns plain values."""
from lpy_api import case


@case("Lstring", "Lstring.__len__", "Lstring.__str__")
def lstring_from_text():
    from openalea.lpy import Lstring

    s = Lstring("A(1)[B(2,3)]C")
    return [len(s), str(s)]


@case("Lstring.__getitem__")
def lstring_index_out_of_range():
    from openalea.lpy import Lstring

    return Lstring("A B")[5]
