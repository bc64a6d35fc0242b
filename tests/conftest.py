import pytest

from interplay.motion.clip import save_clips
from tests.helpers.postgres import pg_cluster, pg_url  # noqa: F401  (fixtures: a real PostgreSQL)
from tests.helpers.synthetic_motion import stand_in_clips


@pytest.fixture(scope="session")
def stand_in_dir(tmp_path_factory):
    out = tmp_path_factory.mktemp("stand_in_data")
    save_clips(stand_in_clips(), out)
    return out
