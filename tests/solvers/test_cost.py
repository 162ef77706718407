"""The memory estimate before a model is built (issue 33 item 4): the band solve's bytes
counted by hand, and the refusal above the share of the available memory."""
from ancf.solvers.cost import MEMORY_SHARE, affordable, band_bytes, grid_bytes


def test_a_plate_grid_is_counted_as_its_nodes_band_and_element_blocks():
    """1024 x 64 plate36 elements: 9 x 1025 x 65 = 599625 unknowns, half-band 9 x 66 = 594,
    65536 elements of 36 coordinates: 8 x 8 x 65536 x 36^2 + 4 x 8 x 599625 x 1783 bytes."""
    by_hand = 8 * 8 * 65536 * 36**2 + 4 * 8 * 599625 * (3 * 594 + 1)
    assert grid_bytes(1024, 64, 9) == band_bytes(599625, 594, 65536, 36) == by_hand
    assert abs(by_hand / 1e9 - 39.648) < 1e-3


def test_a_solve_above_the_share_of_the_memory_is_refused_naming_the_estimate():
    gb = 1e9
    assert affordable(MEMORY_SHARE * 10 * gb, "x", "less", available=10 * gb) is None
    refused = affordable(39.6 * gb, "n_elements = 1024: the model", "a coarser mesh",
                         available=20 * gb)
    assert refused == ("n_elements = 1024: the model would need about 39.6 GB, above 0.5 of "
                       "the 20 GB available; allowed: a coarser mesh")
