# Type stubs of trailray.dask.
from typing import Any, Callable, List, NamedTuple, Optional, Sequence, Tuple, Union

from . import Heatmap, _Path

class Failure(NamedTuple):
    path: str
    error: str

def heatmap(files: Union[_Path, Sequence[_Path]], client: Any = None, partitions: Optional[int] = None,
            cell: float = 50.0, of: str = "tracks", bbox: Optional[Tuple[float, float, float, float]] = None,
            strict: bool = False) -> Heatmap: ...
def map_files(function: Callable[[str], Any], files: Union[_Path, Sequence[_Path]], client: Any = None) -> List[Any]: ...
