def outputs(d):
    return []
