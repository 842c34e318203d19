# The core builds for Cortex-M with arm-none-eabi-gcc and newlib, warning-free.
set -euo pipefail
make lib CC=arm-none-eabi-gcc AR=arm-none-eabi-ar BUILD=build-arm-lib WERROR=1 \
    CFLAGS="-Os -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16"
WERROR=1 make firmware
