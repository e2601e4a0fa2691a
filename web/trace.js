// A run's trace, as the native library's `sim::trace` writes it (crates/coulomb-hands-web):
// every TRACE_EVERY steps and at the end, the objects' states and the contacts as the bits of
// their 32-bit floats in hexadecimal, joined by `|`. Equal traces are equal runs, bit for bit.
export const TRACE_EVERY = 250;

export function hex(floats) {
  const bits = new Uint32Array(floats.buffer, floats.byteOffset, floats.length);
  let out = '';
  for (const b of bits) out += b.toString(16).padStart(8, '0');
  return out;
}

export function traceRow(world) {
  return `${hex(world.objectStates())}|${hex(world.contacts())}`;
}
