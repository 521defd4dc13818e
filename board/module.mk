# board/: the board's side of the protocol, as firmware or a soft core runs it (docs/board.md): the engine
# ef_board.c, the DUT adaptors behind it (dut_model.c: the model's timing model; dut_rtl.*: the Verilated
# ef_raster, board/rtl_dut.mk) and the GPIO bus's board end.  It may include proto/ and the public headers,
# never host/ or cli/ (tests/layers checks it).
BOARD_SRC := $(wildcard board/*.c)
BOARD_OBJ := $(BOARD_SRC:%.c=$(BUILD)/%.o)
LAYER_INC_board := -Iinclude/edgeflag -Ifixed -Irtl_vectors -Iboard -Iproto
$(BOARD_OBJ): EF_INC := $(LAYER_INC_board)
