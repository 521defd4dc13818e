# board/firmware/firmware.mk - the ULX3S board's firmware: board/ef_board.c and
# proto/ef_frame.c compiled unchanged, with main.c (the engine), its links (link_*.c), dut_soc.c and crc32.c, by
# Debian's riscv64-unknown-elf-gcc against picolibc, for the SoC's VexRiscv
# (rv32i).  Included by the Makefile; FW_SOC names the SoC build folder whose
# software/include/generated headers (csr.h, soc.h, mem.h, regions.ld) it
# follows; the image goes to $(FW_OUT).bin (default $(FW_SOC)/firmware.bin).  FW_EXTRA: more
# compiler flags (tests/board/soc_sim.sh plants a fault with -DEF_SOC_FAULT_PIX).
#   make firmware FW_SOC=build/board/ulx3s-25f-ns8
#   EF_BOARD_SERIAL=...  the serial number identify reports (default EFULX3S-0001)
FW_CC ?= riscv64-unknown-elf-gcc
FW_OBJCOPY ?= riscv64-unknown-elf-objcopy
FW_SIZE ?= riscv64-unknown-elf-size
EF_BOARD_SERIAL ?= EFULX3S-0001
FW_LITEX_INC = $(shell $(EF_VENV_PY) -c 'import litex, os; print(os.path.join(os.path.dirname(litex.__file__), "soc/software/include"))' 2>/dev/null)
FW_MARCH ?= rv32im
# Layer: its own folder, the board engine, the protocol and the public headers; never host/, cli/,
# util/ or the model's internals (tests/layers checks it).
LAYER_INC_firmware := -Iboard/firmware -Iboard -Iproto -Iinclude/edgeflag
FW_CFLAGS = -march=$(FW_MARCH) -mabi=ilp32 --specs=picolibc.specs -Os -flto -std=gnu11 -Wall -Wextra -Werror \
            -ffunction-sections -fdata-sections -DEF_BOARD_SERIAL='"$(EF_BOARD_SERIAL)"' \
            $(LAYER_INC_firmware) -I$(FW_SOC)/software/include -isystem $(FW_LITEX_INC) -isystem $(FW_LITEX_INC)/../../cores/cpu/vexriscv
FW_OUT ?= $(FW_SOC)/firmware
FW_EXTRA ?=
# the links (board/firmware/link.h): each file compiles to nothing when the SoC lacks its core
FW_LINKS = board/firmware/link_uart.c board/firmware/link_gpio.c board/firmware/link_usb.c
FW_SRC = board/firmware/crt0.S board/firmware/main.c $(FW_LINKS) board/firmware/dut_soc.c board/firmware/crc32.c \
         board/firmware/mem.c board/firmware/bench.c \
         board/ef_board.c proto/ef_frame.c

$(FW_OUT).elf: $(FW_SRC) board/firmware/linker.ld board/firmware/*.h board/ef_board.h proto/ef_frame.h \
                        proto/ef_proto.h $(FW_SOC)/software/include/generated/csr.h
	$(FW_CC) $(FW_CFLAGS) $(FW_EXTRA) -nostartfiles -T board/firmware/linker.ld -L$(FW_SOC)/software/include \
	    -Wl,--gc-sections -Wl,-Map=$(FW_OUT).map -o $@ $(FW_SRC)
	$(FW_SIZE) $@

$(FW_OUT).bin: $(FW_OUT).elf
	$(FW_OBJCOPY) -O binary $< $@
