/* SPDX-License-Identifier: MIT */
/*
 * A zl_panel_bus (zline's SPI panel driver, zl_spi_panel.h) on Arduino's
 * SPI class and three digital pins: chip select, data/command and reset.
 * Blocking writes (no write_start): use it with one colour buffer.
 * Copy this file and arduino_spi_bus.cpp into your sketch to drive a panel.
 */
#ifndef ARDUINO_SPI_BUS_H
#define ARDUINO_SPI_BUS_H

#include <stdint.h>

#include <zl_spi_panel.h>

struct ArduinoSpiPins {
    uint8_t cs, dc, reset; /* reset: 0xff when the module's reset is not wired */
    uint32_t clock_hz;     /* SPI clock; the AVR's SPI tops out at F_CPU / 2 */
};

/* Fill *bus for these pins (which must outlive the bus), set the pins up,
 * pulse reset and start SPI. */
void arduino_spi_bus_begin(zl_panel_bus *bus, const ArduinoSpiPins *pins);

#endif
