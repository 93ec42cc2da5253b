def scene_report(scene, module):
    raise NotImplementedError
