# proto/: the board protocol's wire layer (docs/board.md sections 2-3): frame layout, CRC-32, message
# types and field layouts.  Below both ends: the board engine (board/) and edgeflag-host (host/) use it;
# it includes nothing but itself (tests/layers checks it).
PROTO_SRC := $(wildcard proto/*.c)
PROTO_OBJ := $(PROTO_SRC:%.c=$(BUILD)/%.o)
LAYER_INC_proto := -Iproto
$(PROTO_OBJ): EF_INC := $(LAYER_INC_proto)
