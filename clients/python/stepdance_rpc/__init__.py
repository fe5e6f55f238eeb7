"""Python client for a Stepdance board's RPC interface (see docs/rpc.md).

    from stepdance_rpc import Board
    with Board("/dev/ttyACM0") as board:          # or the simulator's "serial driver: /dev/pts/N"
        board.tbi.add_move(1, 50, 10, 20, 0, 0, 0, 0)
        print(board.encoder_1.read(), board.tbi.speed_override)
        board.tbi.speed_override = 0.5

Importing this package opens nothing and runs nothing.
"""
from .client import Board, RpcError, RpcTimeout

__all__ = ["Board", "RpcError", "RpcTimeout"]
