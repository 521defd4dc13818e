# The socket transport's tests (docs/board.md section 5.5): `make test-host-socket`, a stage of
# `make test` (under a minute): edgeflag-host against tests/host/pyboard.py (a board written
# from docs/board.md alone) and against sockboard (the board engine behind a unix socket).
SOCKBOARD := $(BUILD)/tests/host/sockboard

# (and tests/host/serial.mk's ptyboard: the board engine behind a pseudo-terminal)
PTYBOARD := $(BUILD)/tests/host/ptyboard

$(SOCKBOARD:%=%.o) $(PTYBOARD:%=%.o): $(BUILD)/tests/host/%.o: tests/host/%.c
	@mkdir -p $(dir $@)
	$(CC) $(CPPFLAGS) -Ihost -Iboard -Iproto -Iutil $(CFLAGS_ALL) -c $< -o $@

$(SOCKBOARD) $(PTYBOARD): %: %.o $(HOST_BOARD_OBJ) $(UTIL_OBJ) $(VEC_A) $(LIB_A)
	$(CC) $(LDFLAGS_ALL) -o $@ $^ $(PNG_LIBS) $(EXPAT_LIBS) $(VEC_LIBS) -lz

.PHONY: test-host-socket
test-host-socket: cli host $(SOCKBOARD)
	@bash tests/host/socket.sh $(BUILD)
