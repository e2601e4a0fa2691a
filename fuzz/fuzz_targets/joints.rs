#![no_main]

#[path = "../entry.rs"]
#[allow(dead_code)]
mod entry;
#[path = "../mutator.rs"]
mod mutator;

libfuzzer_sys::fuzz_target!(|data: &[u8]| entry::run("joints", data));
libfuzzer_sys::fuzz_mutator!(|data: &mut [u8], size: usize, max_size: usize, seed: u32| {
    mutator::mutate(data, size, max_size, seed)
});
