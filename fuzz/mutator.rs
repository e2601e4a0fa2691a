//! A custom libFuzzer mutator for text inputs: half the time it swaps one
//! number of the input for an extreme one (overflowing `f32`, tiny, huge
//! integers), which byte mutations of JSON or OBJ text seldom reach; the
//! other half is libFuzzer's own mutation.

const EXTREMES: [&str; 24] = [
    "1e38",
    "3.5e38",
    "-3.5e38",
    "1e308",
    "-1e308",
    "1e-38",
    "1e-45",
    "1e-320",
    "1e30",
    "-1e30",
    "1e-30",
    "1e20",
    "1e4",
    "10001",
    "0",
    "-0.0",
    "-1",
    "2",
    "65",
    "0.5",
    "4294967296",
    "9223372036854775807",
    "-9223372036854775808",
    "18446744073709551616",
];

/// Byte ranges of the input's number tokens: a run of number characters
/// starting with a digit or `-` just after a separator.
fn numbers(data: &[u8]) -> Vec<(usize, usize)> {
    let is_number = |b: u8| b.is_ascii_digit() || b"+-.eE".contains(&b);
    let mut out = Vec::new();
    let mut i = 0;
    while i < data.len() {
        let after_separator = i == 0 || b" \t\r\n:,[/".contains(&data[i - 1]);
        if after_separator && (data[i].is_ascii_digit() || data[i] == b'-') {
            let start = i;
            while i < data.len() && is_number(data[i]) {
                i += 1;
            }
            out.push((start, i));
        } else {
            i += 1;
        }
    }
    out
}

/// Mutates `data[..size]` in place, returning the new size (≤ `max_size`).
pub fn mutate(data: &mut [u8], size: usize, max_size: usize, seed: u32) -> usize {
    let mut r = seed as usize;
    if r % 2 == 0 {
        r /= 2;
        let spans = numbers(&data[..size]);
        if !spans.is_empty() {
            let (a, b) = spans[r % spans.len()];
            let new = EXTREMES[(r / spans.len()) % EXTREMES.len()].as_bytes();
            let len = size - (b - a) + new.len();
            if len <= max_size {
                let tail = data[b..size].to_vec();
                data[a..a + new.len()].copy_from_slice(new);
                data[a + new.len()..len].copy_from_slice(&tail);
                return len;
            }
        }
    }
    libfuzzer_sys::fuzzer_mutate(data, size, max_size)
}
