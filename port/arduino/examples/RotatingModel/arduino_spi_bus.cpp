// SPDX-License-Identifier: MIT
// zl_panel_bus on Arduino's SPI class: see arduino_spi_bus.h.
#include "arduino_spi_bus.h"

#include <Arduino.h>
#include <SPI.h>

static const ArduinoSpiPins *pins_of(void *user)
{
    return static_cast<const ArduinoSpiPins *>(user);
}

// Both controllers sample on the rising edge with the clock idle low
// (SPI mode 0), most significant bit first.
static void bus_select(void *user, int selected)
{
    const ArduinoSpiPins *p = pins_of(user);
    if (selected) {
        SPI.beginTransaction(SPISettings(p->clock_hz, MSBFIRST, SPI_MODE0));
        digitalWrite(p->cs, LOW);
    } else {
        digitalWrite(p->cs, HIGH);
        SPI.endTransaction();
    }
}

static void bus_set_dc(void *user, int data)
{
    digitalWrite(pins_of(user)->dc, data ? HIGH : LOW);
}

// SPI.transfer(buffer, n) overwrites the buffer with what comes back; the
// rows zline hands over are const, so they go byte by byte.
static void bus_write(void *user, const uint8_t *bytes, size_t count)
{
    (void)user;
    for (size_t i = 0; i < count; i++)
        SPI.transfer(bytes[i]);
}

static void bus_delay_ms(void *user, uint32_t ms)
{
    (void)user;
    delay(ms);
}

void arduino_spi_bus_begin(zl_panel_bus *bus, const ArduinoSpiPins *pins)
{
    pinMode(pins->cs, OUTPUT);
    digitalWrite(pins->cs, HIGH);
    pinMode(pins->dc, OUTPUT);
    if (pins->reset != 0xff) { // a hardware reset before the driver's SWRESET
        pinMode(pins->reset, OUTPUT);
        digitalWrite(pins->reset, LOW);
        delay(10);
        digitalWrite(pins->reset, HIGH);
        delay(120);
    }
    SPI.begin();
    bus->user = const_cast<ArduinoSpiPins *>(pins);
    bus->select = bus_select;
    bus->set_dc = bus_set_dc;
    bus->write = bus_write;
    bus->write_start = NULL; // blocking writes: one colour buffer
    bus->write_wait = NULL;
    bus->delay_ms = bus_delay_ms;
    bus->status = NULL; // SPI.transfer cannot report a failure
}
