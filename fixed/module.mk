FIXED_SRC := $(wildcard fixed/*.c)
FIXED_OBJ := $(FIXED_SRC:%.c=$(BUILD)/%.o)
# Layer: the bottom one, fixed/ alone.
LAYER_INC_fixed := -Ifixed
$(FIXED_OBJ): EF_INC := $(LAYER_INC_fixed)
