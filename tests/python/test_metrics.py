"""The path tracer and image metrics from Python: the metrics voxgi compare prints, beside the
black and constant baselines on the same reference."""
import numpy as np
import pytest

import voxgi


@pytest.fixture(scope="module")
def reference(box):
    return voxgi.path_trace(box, spp=16, threads=2)


def test_the_path_tracer_gives_an_image_and_its_variance(reference):
    assert reference["image"].shape == (64, 64, 3) and reference["image"].dtype == np.float32
    assert reference["variance"].shape == (64, 64, 3)
    assert reference["image"].mean() > 0 and (reference["variance"] >= 0).all()
    assert reference["rays"] > 64 * 64 * 16


def test_the_metrics_stand_beside_their_baselines(box, reference):
    image = voxgi.render(box, threads=2)
    m = voxgi.compare(image, reference["image"])
    black = m["baselines"]["black"]
    assert 0 < m["rel_mse"] < black["rel_mse"]
    # a black image scores relMSE ~1 in units of the reference's mean, and no energy
    np.testing.assert_allclose(black["energy"], [0, 0, 0])
    assert voxgi.compare(reference["image"], reference["image"])["rel_mse"] == 0.0
    # the constant baseline is the reference's mean per channel
    constant = np.broadcast_to(reference["image"].mean(axis=(0, 1)), image.shape)
    assert voxgi.compare(constant, reference["image"])["rel_mse"] == pytest.approx(
        m["baselines"]["constant"]["rel_mse"], rel=1e-5)


def test_a_mask_keeps_its_pixels(reference):
    """The masked metrics are those of the kept pixels alone: the left half 1.5 times too bright
    and the right half, outside the mask, 3 times; a mask ignored would count the right half."""
    image = reference["image"]
    mask = np.zeros(image.shape[:2], bool)
    mask[:, :32] = True
    test = image * 1.5
    test[:, 32:] = image[:, 32:] * 3.0
    masked = voxgi.compare(test, image, mask=mask)
    assert masked["pixels"] == 64 * 32
    left = voxgi.compare(np.ascontiguousarray(test[:, :32]), np.ascontiguousarray(image[:, :32]))
    for key in ("rmse", "rel_mse", "mare"):
        assert masked[key] == pytest.approx(left[key], rel=1e-6), key
    assert voxgi.compare(test, image)["rmse"] > 1.5 * masked["rmse"]
