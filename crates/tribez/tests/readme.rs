//! The README's "Use as a library" program is `examples/library.rs`, byte for byte, and it runs
//! (the example is built as a crate of its own that depends on tribez, as a user's is).

mod library {
    include!("../examples/library.rs");

    pub fn run() -> Result<(), tribez::Error> {
        main()
    }
}

#[test]
fn the_readme_library_program_is_the_example_and_runs() {
    let readme = include_str!("../../../README.md");
    let at = readme
        .find("## Use as a library")
        .expect("README has a section `## Use as a library`");
    let section = &readme[at..];
    let open = "```rust\n";
    let start = section
        .find(open)
        .expect("the section has a rust code block")
        + open.len();
    let len = section[start..].find("```").expect("the block is closed");
    assert_eq!(
        &section[start..start + len],
        include_str!("../examples/library.rs"),
        "README.md's first rust block under `## Use as a library` must equal crates/tribez/examples/library.rs"
    );
    library::run().expect("the example runs");
}
