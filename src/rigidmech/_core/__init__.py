"""Internal foundations shared by every layer: errors, validation, compilation."""
