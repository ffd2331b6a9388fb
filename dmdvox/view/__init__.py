"""Pictures of results: headless PNG renderings of meshes and fields."""
