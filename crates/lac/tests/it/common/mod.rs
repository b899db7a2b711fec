pub(crate) mod space_inputs;
