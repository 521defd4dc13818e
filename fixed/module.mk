FIXED_SRC := $(wildcard fixed/*.c)
FIXED_OBJ := $(FIXED_SRC:%.c=$(BUILD)/%.o)
