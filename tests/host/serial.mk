# The serial transport's tests (docs/board-serial.md): `make test-host-serial`, a stage of `make test`
# (under 90 s): edgeflag-host --transport serial against tests/host/ptyboard (built by socket.mk: the
# board engine behind a pseudo-terminal, or a relay with a rate limit and wire faults in front of
# another board's pty).  tests/host/serial.sh BUILD [BOARD_CMD] runs the same set against any board
# that prints its pty.
.PHONY: test-host-serial
test-host-serial: cli host $(PTYBOARD)
	@bash tests/host/serial.sh $(BUILD)
